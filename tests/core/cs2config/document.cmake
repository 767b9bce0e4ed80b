# The .cs2 text format.
target_sources(stellwerk-core-tests PRIVATE
    cs2config/DocumentTest.cpp
)
