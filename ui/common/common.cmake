# What several features share: the words and lamps for station state ("not reported", the status dots, the
# track power line, the "layout stopped" banner, the red bar of a file's problem), the railway's locomotives
# as a table, the row index of such tables, greys that keep their contrast, the function keys' and the
# toolbars' icons, two parts side by side or stacked and widgets wrapping into rows as a panel's width
# allows, the wheel that only scrolls past a panel's controls, where the remembered settings live, and
# the dialog that places a train for the automation (the Automatic panel and the track plan both open it).
target_sources(stellwerk-ui PRIVATE
    common/Contrast.cpp common/Contrast.h
    common/FunctionIcons.cpp common/FunctionIcons.h
    common/LayoutStateBanner.cpp common/LayoutStateBanner.h
    common/LocomotiveMime.cpp common/LocomotiveMime.h
    common/LocomotivePictureBook.cpp common/LocomotivePictureBook.h
    common/PlaceTrainDialog.cpp common/PlaceTrainDialog.h
    common/LocomotiveTableModel.cpp common/LocomotiveTableModel.h
    common/NotReported.cpp common/NotReported.h
    common/PowerStatus.cpp common/PowerStatus.h
    common/ProblemBar.cpp common/ProblemBar.h
    common/RowIndex.h
    common/SideBySide.cpp common/SideBySide.h
    common/StatusDot.cpp common/StatusDot.h
    common/StellwerkSettings.h
    common/ToolIcons.cpp common/ToolIcons.h
    common/WheelGuard.cpp common/WheelGuard.h
    common/WrappingGrid.cpp common/WrappingGrid.h
)

# The toolbars' drawings (resources/tool-icons), embedded as :/tool-icons/<name>.svg.
set(stellwerk_tool_icons add-throttle blocks connect export-layout fit open-layout station-plan zoom-in zoom-out)
list(TRANSFORM stellwerk_tool_icons PREPEND ${PROJECT_SOURCE_DIR}/resources/tool-icons/)
list(TRANSFORM stellwerk_tool_icons APPEND .svg)
qt_add_resources(stellwerk-ui stellwerk_tool_icons
    PREFIX /tool-icons
    BASE ${PROJECT_SOURCE_DIR}/resources/tool-icons
    FILES ${stellwerk_tool_icons})

# The function keys' drawings (resources/function-icons), embedded as :/function-icons/<kind>.svg, for the
# throttles and the locomotive editor.
set(stellwerk_function_icons
    announcement bell brake-sound cab-light coupler horn inertia interior-light light pantograph shunting
    smoke sound whistle)
list(TRANSFORM stellwerk_function_icons PREPEND ${PROJECT_SOURCE_DIR}/resources/function-icons/)
list(TRANSFORM stellwerk_function_icons APPEND .svg)
qt_add_resources(stellwerk-ui stellwerk_function_icons
    PREFIX /function-icons
    BASE ${PROJECT_SOURCE_DIR}/resources/function-icons
    FILES ${stellwerk_function_icons})
