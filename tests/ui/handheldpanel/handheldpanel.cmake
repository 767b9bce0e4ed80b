# The Handhelds panel on the demo's station (watching) and on a bus where Stellwerk is the MS1s' master.
target_sources(stellwerk-ui-tests PRIVATE
    handheldpanel/HandheldsPanelTest.cpp
)
