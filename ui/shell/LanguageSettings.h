#pragma once

#include "shell/Language.h"

namespace stellwerk::ui {

// The user's choice of interface language, remembered between runs in Stellwerk's settings
// (organisation and application "Stellwerk"); until a choice is made, the system's language decides.
class LanguageSettings final {
public:
    static Language load();
    static void save(Language language);
};

} // namespace stellwerk::ui
