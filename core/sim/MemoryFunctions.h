#pragma once

#include "sim/StationLayout.h"
#include "sim/StationState.h"

#include <cstdint>

namespace stellwerk::sim {

// Chapter 9: the station's memory. A request of memory function n ("A1" = 1, "B1" = 9, ... "z8" = 416) for
// the master (device 0) or for the station's own device id runs route n of fahrstrassen.cs2: the station
// announces it running (status 2), switches its accessories in order (nested routes too) as the keyboard
// does, and announces it activated (1). Release (position 0) announces it deactivated (0); a slot without a
// route, or a route that cannot run, is announced as a run error (255). Requests for other devices are
// theirs.
class MemoryFunctions {
public:
    MemoryFunctions(const StationLayout& layout, StationState& state);

    bool handle(const cs2::Message& message, Outbox& out);

    // Routes nest at most this deep (a route running itself stops there).
    static constexpr int MaxDepth = 8;

private:
    bool run(std::int64_t route, int depth, Outbox& out);
    void switchAccessory(std::int64_t keyboardNumber, std::int64_t position, Outbox& out);

    const StationLayout& layout_;
    StationState& state_;
};

} // namespace stellwerk::sim
