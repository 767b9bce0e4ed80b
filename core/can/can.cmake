# The CAN frame every protocol on the bus shares (core/can): pure C++, no dependency.
stellwerk_core_library(can PURE)
target_sources(stellwerk-can PRIVATE
    can/CanFrame.cpp
    can/CanFrame.h
)
