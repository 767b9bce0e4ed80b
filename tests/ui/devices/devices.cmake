# The Devices panel against simulated RO modules and OpenRailCAN devices behind a gateway on loopback.
target_sources(stellwerk-ui-tests PRIVATE
    devices/DevicesPanelTest.cpp
    devices/DevicesEditingTest.cpp
    devices/DevicesRig.h
)
