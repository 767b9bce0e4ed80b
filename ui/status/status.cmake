# The Status page: a gauge per reading of each device, the overload banner, and a device's configuration
# channels.
target_sources(stellwerk-ui PRIVATE
    status/DeviceSettingEditor.cpp status/DeviceSettingEditor.h
    status/GaugeWidget.cpp status/GaugeWidget.h
    status/StatusPanel.cpp status/StatusPanel.h
)
