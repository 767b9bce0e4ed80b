# transports sources of stellwerk-transport (core/transport): UDP, TCP, QCanBus and in-process loopback transports.
stellwerk_core_library(transport)
target_sources(stellwerk-transport PRIVATE
    transport/CanBusTransport.cpp
    transport/CanBusTransport.h
    transport/DurationText.cpp
    transport/DurationText.h
    transport/FrameAssembler.cpp
    transport/LocalPeer.h
    transport/LoopbackTransport.cpp
    transport/LoopbackTransport.h
    transport/NetworkFraming.cpp
    transport/Reconnector.cpp
    transport/SendQueue.cpp
    transport/TcpTransport.cpp
    transport/TcpTransport.h
    transport/Transport.cpp
    transport/Transport.h
    transport/TransportAddress.cpp
    transport/TransportFactory.cpp
    transport/UdpTransport.cpp
    transport/UdpTransport.h
)
target_link_libraries(stellwerk-transport PUBLIC stellwerk-can stellwerk-base Qt6::Core Qt6::Network Qt6::SerialBus)
