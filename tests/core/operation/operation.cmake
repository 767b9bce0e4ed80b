# operation tests (tests/core/operation): the book of trains, its JSON and its file (written, read again, a
# damaged one put aside), and where it is kept for a station and for an opened folder. The demo layout's
# folder comes from the track graph tests' definition (STELLWERK_DEMO_LAYOUT_DIR).
target_sources(stellwerk-core-tests PRIVATE
    operation/TrainBookTest.cpp
)
target_link_libraries(stellwerk-core-tests PRIVATE stellwerk-operation)
