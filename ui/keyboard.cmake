# The turnout panel: the station's keyboard as pages of keys with our own drawings of the article types.
target_sources(stellwerk-ui PRIVATE
    AccessoryIcon.cpp AccessoryIcon.h
    TurnoutKey.cpp TurnoutKey.h
    TurnoutPanel.cpp TurnoutPanel.h
)

