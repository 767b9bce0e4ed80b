# The track plan tab: pages of the CS2 gleisbild drawn as vector tiles, live states, switching by click.
target_sources(stellwerk-ui PRIVATE
    trackplan/FeatureShapes.cpp
    trackplan/LayoutFileActions.cpp trackplan/LayoutFileActions.h
    trackplan/LayoutFileDialog.cpp trackplan/LayoutFileDialog.h
    trackplan/LayoutFileSettings.cpp trackplan/LayoutFileSettings.h
    trackplan/SignalShapes.cpp
    trackplan/TrackColors.cpp trackplan/TrackColors.h
    trackplan/NameElision.cpp trackplan/NameElision.h
    trackplan/PageZoom.cpp trackplan/PageZoom.h
    trackplan/PaintBands.cpp trackplan/PaintBands.h
    trackplan/PaintThreads.cpp trackplan/PaintThreads.h
    trackplan/SetRoutes.cpp trackplan/SetRoutes.h
    trackplan/TileMenu.cpp trackplan/TileMenu.h
    trackplan/TileTag.cpp trackplan/TileTag.h
    trackplan/TrackPageView.cpp trackplan/TrackPageView.h
    trackplan/TrackPlanPanel.cpp trackplan/TrackPlanPanel.h
    trackplan/TrackShapes.cpp trackplan/TrackShapes.h
    trackplan/TrackTileCache.cpp trackplan/TrackTileCache.h
    trackplan/TrackTileInfo.cpp trackplan/TrackTileInfo.h
    trackplan/TrackTileLook.h
    trackplan/TrackTilePainter.cpp trackplan/TrackTilePainter.h
    trackplan/TurnoutShapes.cpp
)
