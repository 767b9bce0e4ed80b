# locomotives tests (tests/core/cs2config)
target_sources(stellwerk-core-tests PRIVATE
    cs2config/LocomotiveCorpusQuirksTest.cpp
    cs2config/LocomotiveDocumentExampleTest.cpp
    cs2config/LocomotiveEditorTest.cpp
    cs2config/LocomotiveFileTest.cpp
    cs2config/LocomotiveFuzzTest.cpp
    cs2config/LocomotivePictureTest.cpp
    cs2config/LocomotiveStateFileTest.cpp
    cs2config/Ms2StreamTest.cpp
)
