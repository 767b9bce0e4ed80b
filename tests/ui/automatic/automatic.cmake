# The Automatic panel against the demo's simulated CS2 on loopback: placing, starting, a fault's sentence,
# the schedule editor writing the book, unsaved edits asked about, English and German.
target_sources(stellwerk-ui-tests PRIVATE
    automatic/AutomaticPanelTest.cpp
    automatic/StopReasonTextTest.cpp
)
