# After trouble: what was brought back after a command the station did not confirm (the notice in the
# status bar and its list), the choice of what to bring back, and "Bring the layout back in step".
target_sources(stellwerk-ui PRIVATE
    aftertrouble/AftermathMenu.cpp aftertrouble/AftermathMenu.h
    aftertrouble/AftermathSettings.cpp aftertrouble/AftermathSettings.h
    aftertrouble/CorrectionNotice.cpp aftertrouble/CorrectionNotice.h
    aftertrouble/CorrectionText.cpp aftertrouble/CorrectionText.h
)
