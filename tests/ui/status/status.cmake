# The Status page on the embedded demo station: gauges per reading, and a device's configuration channels
# written to the station.
target_sources(stellwerk-ui-tests PRIVATE
    status/DeviceSettingsTest.cpp
    status/StatusPanelTest.cpp
)
