# The CS2 CAN codec (core/cs2): pure C++, depends on the frame type (and base's Expected) only.
stellwerk_core_library(cs2 PURE)
target_sources(stellwerk-cs2 PRIVATE
    cs2/AccessoryCodec.cpp
    cs2/Automation.cpp
    cs2/Codec.cpp
    cs2/Crc16.cpp
    cs2/DeviceCodec.cpp
    cs2/FeedbackCodec.cpp
    cs2/Fields.cpp
    cs2/FrameReport.cpp
    cs2/Hash.cpp
    cs2/JsonText.cpp
    cs2/LocoCodec.cpp
    cs2/LocId.cpp
    cs2/LocIdText.cpp
    cs2/SpeedSteps.cpp
    cs2/StreamCodec.cpp
    cs2/SystemCodec.cpp
)
target_link_libraries(stellwerk-cs2 PUBLIC stellwerk-can stellwerk-base)
