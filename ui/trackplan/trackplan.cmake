# The track plan tab: pages of the CS2 gleisbild drawn as vector tiles, live states, switching by click, and
# the track graph's blocks and problems drawn over them, and the automation's trains and reserved ways on them
# (placing a train from a block's menu or by dropping a locomotive on it).
target_sources(stellwerk-ui PRIVATE
    trackplan/AnnouncedStateText.cpp trackplan/AnnouncedStateText.h
    trackplan/BlockDescription.cpp trackplan/BlockDescription.h
    trackplan/BlockLegend.cpp trackplan/BlockLegend.h
    trackplan/BlockOutlines.cpp trackplan/BlockOutlines.h
    trackplan/BlockPopup.cpp trackplan/BlockPopup.h
    trackplan/BlockShades.cpp trackplan/BlockShades.h
    trackplan/BlockViewSettings.cpp trackplan/BlockViewSettings.h
    trackplan/FeatureShapes.cpp
    trackplan/GraphProblemText.cpp trackplan/GraphProblemText.h
    trackplan/LayoutFileActions.cpp trackplan/LayoutFileActions.h
    trackplan/LayoutFileDialog.cpp trackplan/LayoutFileDialog.h
    trackplan/LayoutFileSettings.cpp trackplan/LayoutFileSettings.h
    trackplan/SignalShapes.cpp
    trackplan/TrackColors.cpp trackplan/TrackColors.h
    trackplan/NameElision.cpp trackplan/NameElision.h
    trackplan/PageZoom.cpp trackplan/PageZoom.h
    trackplan/PaintBands.cpp trackplan/PaintBands.h
    trackplan/PaintThreads.cpp trackplan/PaintThreads.h
    trackplan/PlanAutomation.cpp trackplan/PlanAutomation.h
    trackplan/PlanGraph.cpp trackplan/PlanGraph.h
    trackplan/SetRoutes.cpp trackplan/SetRoutes.h
    trackplan/TileMenu.cpp trackplan/TileMenu.h
    trackplan/TileTag.cpp trackplan/TileTag.h
    trackplan/TrackPageView.cpp trackplan/TrackPageView.h
    trackplan/TrackPlanPanel.cpp trackplan/TrackPlanPanel.h
    trackplan/TrackPlanTrains.cpp
    trackplan/TrackShapes.cpp trackplan/TrackShapes.h
    trackplan/TrackTileCache.cpp trackplan/TrackTileCache.h
    trackplan/TrackTileInfo.cpp trackplan/TrackTileInfo.h
    trackplan/TrackTileLook.h
    trackplan/TrackTilePainter.cpp trackplan/TrackTilePainter.h
    trackplan/TrainsOnPlan.cpp trackplan/TrainsOnPlan.h
    trackplan/TurnoutShapes.cpp
)
