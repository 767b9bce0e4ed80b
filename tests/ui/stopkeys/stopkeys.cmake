# The keys that stop the layout and the one that must not (Escape), asserted on the wire; the STOP key's
# one width in all its looks.
target_sources(stellwerk-ui-tests PRIVATE stopkeys/StopKeysTest.cpp stopkeys/StopKeyWidthTest.cpp)
