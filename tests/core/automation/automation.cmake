# automation tests (tests/core/automation): the decisions on the demo's track graph alone (reservations, the
# way chosen, the dispatcher told contacts and turnout answers); the trains on the simulator are in tests/e2e.
target_sources(stellwerk-core-tests PRIVATE
    automation/AutomationTestSupport.h
    automation/DeskOperationTest.cpp
    automation/DispatcherTest.cpp
    automation/PlaceInBlockTest.cpp
    automation/PathChoiceTest.cpp
    automation/ReservationsTest.cpp
    automation/ScheduleTest.cpp
    automation/TurnTest.cpp
)
target_link_libraries(stellwerk-core-tests PRIVATE stellwerk-automation)
