# Which protocol a frame on a bus belongs to (core/bus): pure, above the codecs.
target_sources(stellwerk-core PRIVATE
    bus/FrameClassifier.cpp
    bus/FrameClassifier.h
)
