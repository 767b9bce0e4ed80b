# Trust during a running session: views while the station is silent, reconnecting or has switched the
# power off (against a simulated CS2 on loopback, asserting the wire and the screen), the keys that stop
# and the one that must not, unsaved locomotive edits, and `stellwerk --help` without a display.
target_sources(stellwerk-ui-tests PRIVATE
    StationTrustTest.cpp
    StopKeysTest.cpp
    UnsavedLocomotivesTest.cpp
    CommandLineTest.cpp
    TrustTestSupport.h
)
add_dependencies(stellwerk-ui-tests stellwerk)
target_compile_definitions(stellwerk-ui-tests PRIVATE
    STELLWERK_GUI_BINARY="$<TARGET_FILE:stellwerk>"
    STELLWERK_README="${PROJECT_SOURCE_DIR}/README.md")
