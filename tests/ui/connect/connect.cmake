# The station's status line and the Connect dialog against simulated stations on loopback.
target_sources(stellwerk-ui-tests PRIVATE
    connect/ConnectDialogBusesTest.cpp
    connect/ConnectDialogTest.cpp
    connect/ConnectionStatusTest.cpp
)
