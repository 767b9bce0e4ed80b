# The Automatic panel: every train of the automatic operation with its block, state, destination and
# schedule; placing, starting, stopping, handing back; the schedule editor.
target_sources(stellwerk-ui PRIVATE
    automatic/AutomaticPanel.cpp automatic/AutomaticPanel.h
    automatic/ScheduleDialog.cpp automatic/ScheduleDialog.h
    automatic/StopReasonText.cpp automatic/StopReasonText.h
    automatic/TrainStateText.cpp automatic/TrainStateText.h
)
