# The main window offscreen (menus, docks as a control desk and their fit at laptop and full-HD size, language switching, remembered settings), the
# about box, the German translation file, and `stellwerk --help` without a display.
target_sources(stellwerk-ui-tests PRIVATE
    shell/AboutBoxTest.cpp
    shell/CommandLineTest.cpp
    shell/ControlDeskTest.cpp
    shell/DeskFitTest.cpp
    shell/FileAndHelpMenuTest.cpp
    shell/LanguageSwitchTest.cpp
    shell/LanguageTest.cpp
    shell/MainWindowTest.cpp
    shell/TranslationFileTest.cpp
)
add_dependencies(stellwerk-ui-tests stellwerk)
target_compile_definitions(stellwerk-ui-tests PRIVATE
    STELLWERK_EXPECTED_VERSION="${PROJECT_VERSION}"
    STELLWERK_TRANSLATIONS_DIR="${PROJECT_SOURCE_DIR}/translations"
    STELLWERK_GUI_BINARY="$<TARGET_FILE:stellwerk>"
    STELLWERK_README="${PROJECT_SOURCE_DIR}/README.md")

# The real program's first start on a fresh settings folder under a window manager (openbox on Xvfb) at
# 1366x768 and 1920x1080, in English and German: the framed window and its status bar fit the screen, the
# plan is zoomed large enough for names (TileTag::MinimumTile), no panel scrolls sideways. Skipped (77)
# only where xvfb-run or openbox is missing; scripts/setup.sh installs both.
add_test(NAME ui.FirstStartFitsTheScreenUnderAWindowManager
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/shell/first-start-under-window-manager.sh $<TARGET_FILE:stellwerk> 26)
set_tests_properties(ui.FirstStartFitsTheScreenUnderAWindowManager PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 120)
