#pragma once

#include "automation/Schedule.h"
#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace stellwerk::automation {

// Whether the automation drives a train or a person does (tracking follows both).
enum class TrainMode : std::uint8_t { Manual, Automatic };

// What an automatic train is doing; a manual one is Stopped or Running as tracking sees it.
enum class TrainState : std::uint8_t {
    Waiting,    // standing, looking for a free way (or dwelling at its stop)
    SettingWay, // its way is reserved; waiting until every turnout on it is confirmed in position
    Running,    // at travel speed
    Braking,    // at creep speed, towards its stop
    Stopped,    // standing where it stopped, by the automation or because automation is paused
    Unknown,    // stopped as far as we know: the station went silent while it was driven
    Fault,      // stopped by a fault (ghost on its way, a turnout not confirmed or switched under it)
    Lost,       // did not arrive where expected in time: stopped, to be placed again
};
std::string_view trainStateName(TrainState state);

// A locomotive the automation knows: where it stands on the track graph and what it is doing. Its body
// (the blocks it covers) is kept by Tracking, its way by Reservations.
struct Train {
    std::uint32_t locId = 0;
    std::string name;
    int lengthMm = 200; // lokomotive.cs2 has no length: the simulator's default
    TrainMode mode = TrainMode::Manual;
    TrainState state = TrainState::Stopped;
    std::optional<int> destination;   // the block it runs to
    std::optional<Schedule> schedule; // without one it runs to any free block it may stop in
    bool pushPull = false;            // it may change direction in any block, not only at a terminus
};

} // namespace stellwerk::automation
