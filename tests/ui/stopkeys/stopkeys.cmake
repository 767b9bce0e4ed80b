# The keys that stop the layout and the one that must not (Escape), asserted on the wire.
target_sources(stellwerk-ui-tests PRIVATE stopkeys/StopKeysTest.cpp)
