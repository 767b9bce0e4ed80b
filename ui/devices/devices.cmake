# The Devices page: OpenRailCAN devices and RO modules, their relays, outputs and inputs, RO module
# settings and the bindings of device outputs and inputs to the layout's articles and contacts.
target_sources(stellwerk-ui PRIVATE
    devices/BindingsDialog.cpp devices/BindingsDialog.h
    devices/DeviceTableModel.cpp devices/DeviceTableModel.h
    devices/DevicesPanel.cpp devices/DevicesPanel.h
    devices/HexText.h
    devices/OrcDeviceView.cpp devices/OrcDeviceView.h
    devices/RoModuleDialog.cpp devices/RoModuleDialog.h
    devices/RoModuleView.cpp devices/RoModuleView.h
    devices/SignalGrid.cpp devices/SignalGrid.h
)
