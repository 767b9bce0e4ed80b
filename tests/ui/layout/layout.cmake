# The Layout page on the embedded demo station.
target_sources(stellwerk-ui-tests PRIVATE layout/LayoutOverviewTest.cpp)
