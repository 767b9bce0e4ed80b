# The fuzz targets built with gcc and a replay main (fuzz/ReplayMain.cpp) as ordinary tests of the main
# build: each runs its committed seeds, and the .cs2 targets the real files of ../shared/corpus, once.
# The libFuzzer build itself is fuzz/CMakeLists.txt (scripts/fuzz.sh).
set(STELLWERK_ROOT ${PROJECT_SOURCE_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/targets.cmake)

foreach(target IN LISTS STELLWERK_FUZZ_TARGETS)
    add_executable(fuzz-replay-${target} ${CMAKE_CURRENT_LIST_DIR}/${target}.cpp ${CMAKE_CURRENT_LIST_DIR}/ReplayMain.cpp)
    target_include_directories(fuzz-replay-${target} PRIVATE ${CMAKE_CURRENT_LIST_DIR})
    target_link_libraries(fuzz-replay-${target} PRIVATE stellwerk-cli-commands stellwerk-core stellwerk-orc
        stellwerk-trackgraph stellwerk-z21 stellwerk-withrottle stellwerk-warnings)
    add_test(NAME fuzz-replay-${target}
             COMMAND fuzz-replay-${target} ${CMAKE_CURRENT_LIST_DIR}/seeds/${target})
endforeach()

# The real station files: as a .cs2 file, and sent as a compressed stream and as MS2 text.
set(shared_corpus ${STELLWERK_SHARED_DIR}/corpus)
add_test(NAME fuzz-replay-cs2_document-corpus COMMAND fuzz-replay-cs2_document --prefix=0 ${shared_corpus})
add_test(NAME fuzz-replay-track_graph-corpus COMMAND fuzz-replay-track_graph ${shared_corpus})
add_test(NAME fuzz-replay-config_stream-corpus
         COMMAND fuzz-replay-config_stream --prefix=128 ${shared_corpus} --prefix=129 ${shared_corpus})
