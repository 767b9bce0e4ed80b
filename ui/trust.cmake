# Trust during a running session (ui/): what the views show while the station is silent or reconnecting,
# the power key's looks and the "layout stopped" banner, and the keys that stop the layout.
target_sources(stellwerk-ui PRIVATE
    LayoutStateBanner.cpp LayoutStateBanner.h
    NotReported.cpp NotReported.h
    StopKeyMenu.cpp StopKeyMenu.h
    StopKeySettings.cpp StopKeySettings.h
)
