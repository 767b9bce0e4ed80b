# The track plan tab against the simulated station, each page's zoom and fit, the names on the tiles, every tile
# type drawn in every rotation, and the blocks, ways and problems of the track graph shown on the plan.
target_sources(stellwerk-ui-tests PRIVATE
    trackplan/BlockOutlinesTest.cpp
    trackplan/PageZoomTest.cpp
    trackplan/PaintBandsTest.cpp
    trackplan/TileTagTest.cpp
    trackplan/TrackPlanBlockStatesTest.cpp
    trackplan/TrackPlanAutomationTest.cpp
    trackplan/TrackPlanBlocksTest.cpp
    trackplan/TrackPlanOnDemoStation.h
    trackplan/TrackGraphDrawingTest.cpp
    trackplan/TrackPlanPanelTest.cpp
    trackplan/TrackTileCacheTest.cpp
    trackplan/TrackTilePainterTest.cpp
)
target_compile_definitions(stellwerk-ui-tests PRIVATE STELLWERK_SHARED_DIR="${STELLWERK_SHARED_DIR}"
    STELLWERK_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# The track graph's tile table is checked against the drawings (TrackGraphDrawingTest).
target_link_libraries(stellwerk-ui-tests PRIVATE stellwerk-trackgraph)
