#pragma once

#include "can/CanFrame.h"
#include "mcan/HandleRoles.h"
#include "mcanhandhelds/Handheld.h"

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace stellwerk::mcanhandhelds {

// The handhelds of another master (a CS2, CS1 or ECoS on the same bus), as the frames between them show:
// which MS1 logged in at which node, its name, the locomotive it took and how it drives it, and whether it
// still polls. Stellwerk only watches them; it never answers.
class HandheldWatcher {
public:
    using Clock = std::chrono::steady_clock;

    explicit HandheldWatcher(std::chrono::milliseconds silentAfter) : silentAfter_(silentAfter) {}

    // Reads one M-CAN frame; true when something shown changed.
    bool observe(const can::CanFrame& frame, Clock::time_point now);
    // Marks handhelds silent or offline that stopped polling; true when something shown changed.
    bool tick(Clock::time_point now);
    std::vector<Handheld> handhelds() const;
    // A handheld that was logged in at Stellwerk, watched from now on (Stellwerk stood down as its master).
    void adopt(Handheld handheld, Clock::time_point now);
    void clear();

private:
    // How a locomotive on a handheld's stack runs, as its master told it (speed 0..127, function bits).
    struct LocoValues {
        int speed = 0;
        bool forward = true;
        std::uint32_t functions = 0;
    };
    struct Watched {
        Handheld handheld;
        Clock::time_point lastHeard;
        std::map<std::uint16_t, LocoValues> locos; // by handle: every locomotive it asked about
        std::optional<std::uint16_t> taken;        // the handle of the locomotive it drives
    };

    bool observeSlave(Watched& watched, const mcan::Message& message);
    bool observeLoco(Watched& watched, const mcan::Message& message);
    static void showTaken(Watched& watched);

    std::chrono::milliseconds silentAfter_;
    mcan::HandleRoles roles_;
    std::map<std::uint8_t, Watched> watched_; // by slave node
};

} // namespace stellwerk::mcanhandhelds
