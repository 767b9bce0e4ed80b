# The Handhelds page: the MS1 handhelds on the station's bus, their state, locomotive, name and stack.
target_sources(stellwerk-ui PRIVATE
    handheldpanel/HandheldDetails.cpp handheldpanel/HandheldDetails.h
    handheldpanel/HandheldTableModel.cpp handheldpanel/HandheldTableModel.h
    handheldpanel/HandheldsPanel.cpp handheldpanel/HandheldsPanel.h
)
# The other throttles beside the MS1s: OpenRailCAN throttles and the phones of the Z21 and WiThrottle servers.
target_sources(stellwerk-ui PRIVATE
    handheldpanel/OtherThrottles.cpp handheldpanel/OtherThrottles.h
    handheldpanel/ThrottleTableModel.cpp handheldpanel/ThrottleTableModel.h
)
