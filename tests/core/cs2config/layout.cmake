# layout tests (tests/core/cs2config): the track plan index, its pages, the status file, a layout directory
target_sources(stellwerk-core-tests PRIVATE
    cs2config/LayoutCheckTest.cpp
    cs2config/LayoutFolderTest.cpp
    cs2config/TrackElementTypeTest.cpp
    cs2config/TrackFuzzTest.cpp
    cs2config/TrackLayoutTest.cpp
    cs2config/TrackPageTest.cpp
    cs2config/TrackPlanTest.cpp
    cs2config/TrackPositionTest.cpp
    cs2config/TrackStatusTest.cpp
)
