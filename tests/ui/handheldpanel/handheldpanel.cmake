# The Throttles panel (handheldsPanel) on the demo's station (watching), on a bus where Stellwerk is the
# MS1s' master, and with phones of the Z21 and WiThrottle servers (their test clients come from the core
# tests).
target_sources(stellwerk-ui-tests PRIVATE
    handheldpanel/HandheldsPanelTest.cpp
    handheldpanel/ThrottlesPanelTest.cpp
)
target_include_directories(stellwerk-ui-tests PRIVATE
    ${PROJECT_SOURCE_DIR}/tests/core/z21server ${PROJECT_SOURCE_DIR}/tests/core/withrottleserver)
