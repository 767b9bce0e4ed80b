# Widget tests of the turnout panel, against the demo's simulated CS2.
target_sources(stellwerk-ui-tests PRIVATE keyboard/TurnoutPanelTest.cpp)
