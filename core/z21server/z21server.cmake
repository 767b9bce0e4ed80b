# The Z21 LAN server (core/z21server): Roco's Z21 app and WLANmaus drive the railway through the throttle
# port, on a UDP socket, with the Z21 codec. It needs the model and Qt Network, never a session or transport.
stellwerk_core_library(z21server)
target_sources(stellwerk-z21server PRIVATE
    z21server/Z21Clients.cpp
    z21server/Z21Clients.h
    z21server/Z21Railway.cpp
    z21server/Z21Railway.h
    z21server/Z21Server.cpp
    z21server/Z21Server.h
    z21server/Z21ServerRequests.cpp
)
target_link_libraries(stellwerk-z21server PUBLIC stellwerk-z21 stellwerk-model Qt6::Core Qt6::Network)
