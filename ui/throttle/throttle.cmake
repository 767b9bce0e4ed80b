# The throttles: several throttles side by side or stacked as the panel's width allows, each driving one locomotive, with function keys drawn
# from our own icons (resources/function-icons, embedded as :/function-icons/<kind>.svg).
target_sources(stellwerk-ui PRIVATE
    throttle/FunctionIcons.cpp throttle/FunctionIcons.h
    throttle/FunctionPad.cpp throttle/FunctionPad.h
    throttle/SpeedScale.cpp throttle/SpeedScale.h
    throttle/StyleSheetSupport.cpp throttle/StyleSheetSupport.h
    throttle/ThrottlePanel.cpp throttle/ThrottlePanel.h
    throttle/ThrottleSettings.cpp throttle/ThrottleSettings.h
    throttle/ThrottleWidget.cpp throttle/ThrottleWidget.h
)

set(stellwerk_function_icons
    announcement bell brake-sound cab-light coupler horn inertia interior-light light pantograph shunting
    smoke sound whistle)
list(TRANSFORM stellwerk_function_icons PREPEND ${PROJECT_SOURCE_DIR}/resources/function-icons/)
list(TRANSFORM stellwerk_function_icons APPEND .svg)
qt_add_resources(stellwerk-ui stellwerk_function_icons
    PREFIX /function-icons
    BASE ${PROJECT_SOURCE_DIR}/resources/function-icons
    FILES ${stellwerk_function_icons})
