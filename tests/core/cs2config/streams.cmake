# streams tests (tests/core/cs2config): config-data requests and streams (0x20/0x21).
target_sources(stellwerk-core-tests PRIVATE
    cs2config/ConfigStreamKeysTest.cpp
    cs2config/ConfigStreamPayloadTest.cpp
    cs2config/ConfigStreamReceiverTest.cpp
    cs2config/ConfigStreamRequestTest.cpp
    cs2config/ConfigStreamRoundTripTest.cpp
)
