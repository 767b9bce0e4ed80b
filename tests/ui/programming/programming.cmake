# The Programming page against the embedded simulated CS2, alone and inside the desk.
target_sources(stellwerk-ui-tests PRIVATE
    programming/ProgrammingOnTheDeskTest.cpp
    programming/ProgrammingPanelTest.cpp
)
