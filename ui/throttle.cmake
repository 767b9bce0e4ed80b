# The throttles (ui/): several throttles side by side, each driving one locomotive, with function keys
# drawn from our own icons (resources/function-icons, embedded as :/function-icons/<kind>.svg).
target_sources(stellwerk-ui PRIVATE
    FunctionIcons.cpp FunctionIcons.h
    FunctionPad.cpp FunctionPad.h
    SpeedScale.cpp SpeedScale.h
    StyleSheetSupport.cpp StyleSheetSupport.h
    ThrottlePanel.cpp ThrottlePanel.h
    ThrottleSettings.cpp ThrottleSettings.h
    ThrottleWidget.cpp ThrottleWidget.h
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
