# The turnout panel: the station's keyboard as pages of keys with our own drawings of the article types.
target_sources(stellwerk-ui PRIVATE
    keyboard/AccessoryIcon.cpp keyboard/AccessoryIcon.h
    keyboard/TurnoutKey.cpp keyboard/TurnoutKey.h
    keyboard/TurnoutPanel.cpp keyboard/TurnoutPanel.h
)
