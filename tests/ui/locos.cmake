# The Locomotives and Programming pages against the embedded simulated CS2.
target_sources(stellwerk-ui-tests PRIVATE
    ${CMAKE_CURRENT_SOURCE_DIR}/LocomotivePanelTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/ProgrammingPanelTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/UnsavedLocomotivesTest.cpp
)
