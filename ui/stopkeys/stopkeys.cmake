# The keys that stop the layout: the toolbar's STOP / GO key in its three looks, Space and the extra STOP
# key from any widget (Escape only where no popup or dialog is open), and the menu and setting of that key.
target_sources(stellwerk-ui PRIVATE
    stopkeys/EmergencyStopKeys.cpp stopkeys/EmergencyStopKeys.h
    stopkeys/StopGoButton.cpp stopkeys/StopGoButton.h
    stopkeys/StopKeyMenu.cpp stopkeys/StopKeyMenu.h
    stopkeys/StopKeySettings.cpp stopkeys/StopKeySettings.h
)
