# The track plan tab: pages of the CS2 gleisbild drawn as vector tiles, live states, switching by click.
target_sources(stellwerk-ui PRIVATE
    FeatureShapes.cpp
    SignalShapes.cpp
    TrackColors.cpp TrackColors.h
    TrackPageView.cpp TrackPageView.h
    TrackPlanPanel.cpp TrackPlanPanel.h
    TrackShapes.cpp TrackShapes.h
    TrackTileCache.cpp TrackTileCache.h
    TrackTileInfo.cpp TrackTileInfo.h
    TrackTileLook.h
    TrackTilePainter.cpp TrackTilePainter.h
    TurnoutShapes.cpp
)
