# transports sources of stellwerk-core (core/transport): UDP, TCP, QCanBus and in-process loopback transports.
target_sources(stellwerk-core PRIVATE
    transport/CanBusTransport.cpp
    transport/CanBusTransport.h
    transport/FrameAssembler.cpp
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
