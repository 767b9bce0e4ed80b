# The CAN frame every protocol on the bus shares and the ways people write one down (core/can): pure C++.
stellwerk_core_library(can PURE)
target_sources(stellwerk-can PRIVATE
    can/CanFrame.cpp
    can/CanFrame.h
    can/FrameText.cpp
    can/FrameText.h
    can/ReportFields.cpp
    can/ReportFields.h
)
target_link_libraries(stellwerk-can PUBLIC stellwerk-base)
