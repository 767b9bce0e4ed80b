# The throttles: several throttles side by side or stacked as the panel's width allows, each driving one
# locomotive, with function keys drawn from our own icons (common/FunctionIcons).
target_sources(stellwerk-ui PRIVATE
    throttle/FunctionPad.cpp throttle/FunctionPad.h
    throttle/SpeedScale.cpp throttle/SpeedScale.h
    throttle/StyleSheetSupport.cpp throttle/StyleSheetSupport.h
    throttle/ThrottlePanel.cpp throttle/ThrottlePanel.h
    throttle/ThrottleSettings.cpp throttle/ThrottleSettings.h
    throttle/ThrottleWidget.cpp throttle/ThrottleWidget.h
)
