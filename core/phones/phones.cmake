# The desktop's phone servers (core/phones): the Z21 and WiThrottle servers as the settings say, where they
# listen ([HOST:]PORT, shared with the command line's serve) and the Z21 addresses kept in the settings.
stellwerk_core_library(phones)
target_sources(stellwerk-phones PRIVATE
    phones/ListenAddress.cpp
    phones/ListenAddress.h
    phones/PhoneServers.cpp
    phones/PhoneServers.h
    phones/PhoneSettings.cpp
    phones/PhoneSettings.h
)
target_link_libraries(stellwerk-phones PUBLIC stellwerk-z21server stellwerk-withrottleserver stellwerk-model
    Qt6::Core Qt6::Network)
