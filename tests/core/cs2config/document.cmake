# The .cs2 text format, and files recognised by kind.
target_sources(stellwerk-core-tests PRIVATE
    cs2config/ConfigFileTest.cpp
    cs2config/DocumentTest.cpp
    cs2config/TextTest.cpp
)
