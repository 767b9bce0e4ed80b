# A device's configuration channels on the Status page.
target_sources(stellwerk-ui PRIVATE
    DeviceSettingEditor.cpp DeviceSettingEditor.h
)
