# The application around the panels: the main window with its menus, docks and remembered arrangement, the
# railway handed to every panel, the interface language and its translations, the about box, the key list
# and the user guide browser.
target_sources(stellwerk-ui PRIVATE
    shell/AboutBox.cpp shell/AboutBox.h
    shell/ApplicationInfo.cpp shell/ApplicationInfo.h
    shell/FirstWindowSize.cpp shell/FirstWindowSize.h
    shell/GuideBrowser.cpp shell/GuideBrowser.h
    shell/KeyList.cpp shell/KeyList.h
    shell/Language.cpp shell/Language.h
    shell/LanguageMenu.cpp shell/LanguageMenu.h
    shell/LanguageSettings.cpp shell/LanguageSettings.h
    shell/MainWindow.cpp shell/MainWindow.h
    shell/PassingMessage.cpp shell/PassingMessage.h
    shell/Translations.cpp shell/Translations.h
    shell/WindowLayoutSettings.cpp shell/WindowLayoutSettings.h
    shell/Workspace.cpp shell/Workspace.h
)
