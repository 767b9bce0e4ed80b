# The M-CAN codec (core/mcan): the CAN protocol of the Mobile Station 1, CS1 and ECoS. Pure C++, like the
# CS2 codec: the frame type only.
stellwerk_core_library(mcan PURE)
target_sources(stellwerk-mcan PRIVATE
    mcan/Codec.cpp
    mcan/Codec.h
    mcan/CodecDetail.h
    mcan/FlashCodec.cpp
    mcan/FrameReport.cpp
    mcan/FrameReport.h
    mcan/HandleRoles.cpp
    mcan/HandleRoles.h
    mcan/Id.h
    mcan/ListCodec.cpp
    mcan/LoginCodec.cpp
    mcan/Messages.h
    mcan/NameSegments.cpp
    mcan/NameSegments.h
    mcan/SessionCodec.cpp
)
target_link_libraries(stellwerk-mcan PUBLIC stellwerk-can)
