# The simulated CS2's world and network side (core/sim): trains moving on the track graph, the UDP/TCP/HTTP
# servers and the demo layout embedded as the Qt resources :/demo-layout/config/ and :/demo-layout/icons/.
target_sources(stellwerk-simulator PRIVATE
    sim/AccidentWatch.cpp
    sim/AccidentWatch.h
    sim/BusGateway.cpp
    sim/BusGateway.h
    sim/HttpConfigServer.cpp
    sim/HttpConfigServer.h
    sim/StationServer.cpp
    sim/StationServer.h
    sim/TrainMovement.cpp
    sim/TrainMovement.h
    sim/TrainPlacement.cpp
    sim/TrainPlacement.h
    sim/TrainRun.cpp
    sim/TrainRun.h
    sim/TurnoutWatch.cpp
    sim/TurnoutWatch.h
)
# The trains run on the track graph of the station's own plan.
target_link_libraries(stellwerk-simulator PUBLIC stellwerk-trackgraph)

# A static library's resources become an object library that CMake links into every executable using
# stellwerk-simulator, so no Q_INIT_RESOURCE is needed (tests/core/simnet checks that the files are there).
set(demo_layout_dir ${PROJECT_SOURCE_DIR}/resources/demo-layout)
qt_add_resources(stellwerk-simulator demo_layout
    PREFIX /demo-layout
    BASE ${demo_layout_dir}
    FILES
        ${demo_layout_dir}/config/fahrstrassen.cs2
        ${demo_layout_dir}/config/gleisbild.cs2
        ${demo_layout_dir}/config/gleisbilder/Bahnhof.cs2
        ${demo_layout_dir}/config/gleisbilder/Bw.cs2
        ${demo_layout_dir}/config/gleisbilder/Strecke.cs2
        ${demo_layout_dir}/config/lokomotive.cs2
        ${demo_layout_dir}/config/magnetartikel.cs2
)
file(GLOB demo_pictures CONFIGURE_DEPENDS ${demo_layout_dir}/icons/*.png)
qt_add_resources(stellwerk-simulator demo_pictures
    PREFIX /demo-layout
    BASE ${demo_layout_dir}
    FILES ${demo_pictures}
)
