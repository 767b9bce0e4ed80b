# track graph tests (tests/core/trackgraph): every tile type's track, blocks, connections and problems of
# pages drawn in the tests, the demo layout against the table the simulator used before, and the real pages
# of the corpus.
target_sources(stellwerk-core-tests PRIVATE
    trackgraph/TileShapeTest.cpp
    trackgraph/TrackGraphCorpusTest.cpp
    trackgraph/TrackGraphDemoTest.cpp
    trackgraph/TrackGraphPagesTest.cpp
    trackgraph/TrackGraphTest.cpp
)
target_link_libraries(stellwerk-core-tests PRIVATE stellwerk-trackgraph)
target_compile_definitions(stellwerk-core-tests PRIVATE
    STELLWERK_DEMO_LAYOUT_DIR="${PROJECT_SOURCE_DIR}/resources/demo-layout/config")
