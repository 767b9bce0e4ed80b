# The Locomotives page against the embedded simulated CS2, and unsaved locomotive edits never lost without
# asking.
target_sources(stellwerk-ui-tests PRIVATE
    locomotives/LocomotivePanelTest.cpp
    locomotives/UnsavedLocomotivesTest.cpp
)
