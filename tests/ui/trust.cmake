# The keys that stop and the one that must not, unsaved locomotive edits, and `stellwerk --help` without a
# display.
target_sources(stellwerk-ui-tests PRIVATE
    StopKeysTest.cpp
    UnsavedLocomotivesTest.cpp
    CommandLineTest.cpp
)
add_dependencies(stellwerk-ui-tests stellwerk)
target_compile_definitions(stellwerk-ui-tests PRIVATE
    STELLWERK_GUI_BINARY="$<TARGET_FILE:stellwerk>"
    STELLWERK_README="${PROJECT_SOURCE_DIR}/README.md")
