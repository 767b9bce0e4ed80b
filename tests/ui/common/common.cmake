# Trust during a running session: views while the station is silent, reconnecting or has switched the
# power off (against a simulated CS2 on loopback, asserting the wire and the screen). How panels arrange
# their parts for the width they get. The wheel over a panel's controls. Each panel on its own face of the
# connection.
target_sources(stellwerk-ui-tests PRIVATE
    common/PanelArrangementTest.cpp
    common/PanelFacesTest.cpp
    common/PanelWheelTest.cpp
    common/StationTrustTest.cpp
    common/WheelGuardTest.cpp
)
