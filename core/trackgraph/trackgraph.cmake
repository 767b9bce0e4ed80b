# The track graph (core/trackgraph): the railway a track plan shows, derived from the typed files of
# core/cs2config: blocks, the connections between them, and what is wrong with the drawing. Pure C++.
stellwerk_core_library(trackgraph PURE)
target_sources(stellwerk-trackgraph PRIVATE
    trackgraph/BlockNaming.cpp
    trackgraph/BlockPieces.cpp
    trackgraph/GraphAssembly.cpp
    trackgraph/GraphBlocks.cpp
    trackgraph/GraphConnections.cpp
    trackgraph/GraphInvariants.cpp
    trackgraph/GraphReport.cpp
    trackgraph/GraphText.cpp
    trackgraph/PageLinks.cpp
    trackgraph/Problem.cpp
    trackgraph/Stretches.cpp
    trackgraph/TileShape.cpp
    trackgraph/TrackGraph.cpp
    trackgraph/TrackJoints.cpp
    trackgraph/TrackTiles.cpp
    trackgraph/TrainPlacement.cpp
    trackgraph/WaySearch.cpp
)
target_link_libraries(stellwerk-trackgraph PUBLIC stellwerk-cs2config)
