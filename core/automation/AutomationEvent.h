#pragma once

#include "automation/StopReason.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace stellwerk::automation {

// What the automation tells the railway to do; the driver carries it out on the model.
struct DriveCommand {
    enum class Kind : std::uint8_t { Speed, Switch, PowerOff, Reverse };
    Kind kind = Kind::Speed;
    std::uint32_t locId = 0;  // Speed
    int speed = 0;            // Speed: 0..1000
    std::int64_t article = 0; // Switch: keyboard number
    int position = 0;         // Switch

    static DriveCommand speedOf(std::uint32_t locId, int speed) { return {Kind::Speed, locId, speed, 0, 0}; }
    static DriveCommand switching(std::int64_t article, int position) {
        return {Kind::Switch, 0, 0, article, position};
    }
    static DriveCommand powerOff() { return {Kind::PowerOff, 0, 0, 0, 0}; }
    // The locomotive's direction changed (it stands; the station keeps it standing).
    static DriveCommand reverse(std::uint32_t locId) { return {Kind::Reverse, locId, 0, 0, 0}; }

    friend bool operator==(const DriveCommand&, const DriveCommand&) = default;
};

// Something that happened to a train or a block, as the CLI prints it and the panel will show it.
struct AutomationEvent {
    enum class Kind : std::uint8_t {
        Placed,
        Reserved,
        TurnoutSet,
        Departed,
        Entered,
        Braking,
        Stopped,
        Arrived,
        Released,
        Ghost,
        Lost,
        Overrun,
        Fault,
        Manual,    // a throttle took the train: the automation leaves it, its blocks stay reserved
        Automatic, // handed back to the automation where it stands
        Reversed,  // changed direction in its block (push-pull, or at a terminus)
    };
    Kind kind = Kind::Placed;
    std::uint32_t locId = 0; // 0: no train (a ghost)
    int block = 0;           // 0: none
    std::string text;        // a sentence a person can act on
    StopReason reason;       // Fault, Lost, Overrun: why, in parts (text is describe(reason))
};
// "placed", "turnout-set", ... as the CLI prints them.
std::string_view eventKindName(AutomationEvent::Kind kind);

} // namespace stellwerk::automation
