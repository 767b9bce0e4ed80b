# streams sources of stellwerk-cs2config: config-data requests and streams (0x20/0x21).
target_sources(stellwerk-cs2config PRIVATE
    cs2config/ConfigStreamError.cpp
    cs2config/ConfigStreamKeys.cpp
    cs2config/ConfigStreamPayload.cpp
    cs2config/ConfigStreamReceiver.cpp
    cs2config/ConfigStreamRequest.cpp
    cs2config/ConfigStreamRequestCollector.cpp
    cs2config/ConfigStreamSender.cpp
)
