# Which protocol a frame on a bus belongs to (core/bus): pure, above the codecs.
stellwerk_core_library(bus PURE)
target_sources(stellwerk-bus PRIVATE
    bus/FrameClassifier.cpp
    bus/FrameClassifier.h
)
target_link_libraries(stellwerk-bus PUBLIC stellwerk-can)
