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
