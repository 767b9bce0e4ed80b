# Helpers shared by the widget tests: a simulated CS2 on a free loopback port, the demo station with its
# railway bound (keyboard and device settings), and the main window on a station that can fall silent.
target_sources(stellwerk-ui-tests PRIVATE
    support/KeyboardTestSupport.h
    support/MonitorTestSupport.h
    support/StationTestSupport.h
    support/TrustTestSupport.h
)
