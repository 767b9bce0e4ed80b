# The RO relay/IO module codec (core/ro, seed 004): requests, answers, module profiles and the
# little-endian register helpers. Pure C++, like the CS2 and M-CAN codecs: the frame type only.
stellwerk_core_library(ro PURE)
target_sources(stellwerk-ro PRIVATE
    ro/Codec.cpp
    ro/Codec.h
    ro/Exchange.cpp
    ro/Exchange.h
    ro/FrameReport.cpp
    ro/FrameReport.h
    ro/Messages.cpp
    ro/Messages.h
    ro/RegisterFile.cpp
    ro/RegisterFile.h
    ro/RoProfile.cpp
    ro/RoProfile.h
)
target_link_libraries(stellwerk-ro PUBLIC stellwerk-can stellwerk-base)
