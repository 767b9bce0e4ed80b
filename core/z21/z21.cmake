# The Z21 LAN codec (core/z21): the requests of Roco's Z21 app and WLANmaus, and every reply and broadcast
# a Z21 server sends. Pure C++ like the CS2 codec; it links the CS2 codec for its one speed step table.
stellwerk_core_library(z21 PURE)
target_sources(stellwerk-z21 PRIVATE
    z21/LocoSpeed.cpp
    z21/LocoSpeed.h
    z21/Packet.cpp
    z21/Packet.h
    z21/Replies.h
    z21/ReplyCodec.cpp
    z21/ReplyCodec.h
    z21/ReplyEncoding.cpp
    z21/RequestCodec.cpp
    z21/RequestCodec.h
    z21/RequestEncoding.cpp
    z21/Requests.h
)
target_link_libraries(stellwerk-z21 PUBLIC stellwerk-cs2 stellwerk-base)
