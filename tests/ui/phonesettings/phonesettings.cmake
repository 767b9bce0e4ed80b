# Station → Phones… and the status bar's phone count, with the real servers on loopback.
target_sources(stellwerk-ui-tests PRIVATE
    phonesettings/PhonesDialogTest.cpp
)
