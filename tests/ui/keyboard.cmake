# Widget tests of the turnout panel and the Status page's device settings, against the demo's simulated CS2.
target_sources(stellwerk-ui-tests PRIVATE
    TurnoutPanelTest.cpp
    DeviceSettingsTest.cpp
)
