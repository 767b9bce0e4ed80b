# Phones and tablets as throttles: Station → Phones… and the status bar's count of connected phones.
target_sources(stellwerk-ui PRIVATE
    phonesettings/PhonesDialog.cpp phonesettings/PhonesDialog.h
    phonesettings/PhoneStatus.cpp phonesettings/PhoneStatus.h
)
