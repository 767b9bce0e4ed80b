# The OpenRailCAN codec (core/orc): identifier layout, messages of every command group, UIDs and bus ids, the
# frame report. Pure C++, like the CS2 and M-CAN codecs: the frame type only.
stellwerk_core_library(orc PURE)
target_sources(stellwerk-orc PRIVATE
    orc/AccessoryCodec.cpp
    orc/Codec.cpp
    orc/Codec.h
    orc/CodecDetail.h
    orc/FrameReport.cpp
    orc/FrameReport.h
    orc/ManagementCodec.cpp
    orc/MessageBuilder.cpp
    orc/MessageBuilder.h
    orc/Messages.h
    orc/OrcId.h
    orc/SystemCodec.cpp
    orc/Uid.cpp
    orc/Uid.h
)
target_link_libraries(stellwerk-orc PUBLIC stellwerk-can stellwerk-base)
