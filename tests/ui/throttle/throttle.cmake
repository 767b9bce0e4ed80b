# Widget tests of the throttles, against the demo layout's simulated CS2 on loopback.
target_sources(stellwerk-ui-tests PRIVATE throttle/ThrottleTest.cpp)
target_sources(stellwerk-ui-tests PRIVATE throttle/LocomotivePictureTest.cpp)
