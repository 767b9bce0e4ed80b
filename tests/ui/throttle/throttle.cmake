# Widget tests of the throttles, against the demo layout's simulated CS2 on loopback.
target_sources(stellwerk-ui-tests PRIVATE throttle/ThrottleTest.cpp)
target_sources(stellwerk-ui-tests PRIVATE throttle/LocomotivePictureTest.cpp)
# The demo's locomotive pictures, read as a layout's icons folder.
target_compile_definitions(stellwerk-ui-tests PRIVATE
    STELLWERK_DEMO_ICONS_DIR="${PROJECT_SOURCE_DIR}/resources/demo-layout/icons")
