# transports sources of stellwerk-core (core/can): UDP, TCP, QCanBus and in-process loopback transports.
target_sources(stellwerk-core PRIVATE
    can/CanBusTransport.cpp
    can/CanBusTransport.h
    can/FrameAssembler.cpp
    can/LoopbackTransport.cpp
    can/LoopbackTransport.h
    can/NetworkFraming.cpp
    can/Reconnector.cpp
    can/SendQueue.cpp
    can/TcpTransport.cpp
    can/TcpTransport.h
    can/Transport.cpp
    can/Transport.h
    can/TransportAddress.cpp
    can/TransportFactory.cpp
    can/UdpTransport.cpp
    can/UdpTransport.h
)
