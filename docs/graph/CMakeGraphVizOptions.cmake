set(GRAPHVIZ_EXTERNAL_LIBS FALSE)
set(GRAPHVIZ_GENERATE_PER_TARGET FALSE)
set(GRAPHVIZ_GENERATE_DEPENDERS FALSE)
set(GRAPHVIZ_IGNORE_TARGETS "stellwerk-warnings;.*_autogen.*;.*tests.*;.*bench.*;stellwerk-qt-test-main;stellwerk-test-support;fuzz.*;.*_resources_.*;stellwerk-fuzzed;stellwerk-soak")
