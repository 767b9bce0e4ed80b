# After trouble: the notice of what was brought back, its sentences, the choice of what to bring back and
# "Bring the layout back in step", on the desk against a simulated CS2 that stalls.
target_sources(stellwerk-ui-tests PRIVATE
    aftertrouble/AfterTroubleDeskTest.cpp
    aftertrouble/CorrectionTextTest.cpp
)
