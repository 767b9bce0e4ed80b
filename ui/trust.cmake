# The keys that stop the layout: the extra STOP key's menu and setting.
target_sources(stellwerk-ui PRIVATE
    StopKeyMenu.cpp StopKeyMenu.h
    StopKeySettings.cpp StopKeySettings.h
)
