#pragma once

#include "model/UnconfirmedCommands.h"

namespace stellwerk::ui {

// What Stellwerk does after a command the station did not confirm (key `station/afterFailedCommand`):
// bring back what the station last confirmed (the default), or stop every locomotive that had one.
class AftermathSettings final {
public:
    static model::Aftermath load();
    static void save(model::Aftermath aftermath);
};

} // namespace stellwerk::ui
