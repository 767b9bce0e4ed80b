# The Programming page against the embedded simulated CS2.
target_sources(stellwerk-ui-tests PRIVATE programming/ProgrammingPanelTest.cpp)
