#pragma once

#include "sim/StationLayout.h"
#include "sim/StationState.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

namespace stellwerk::sim {

// Chapter 9: the station's memory. A request of memory function n ("A1" = 1, "B1" = 9, ... "z8" = 416) for
// the master (device 0) or for the station's own device id runs route n of fahrstrassen.cs2: the station
// announces it running (status 2), switches its accessories in order (nested routes too), each after the
// wait its step gives (`..sekunde`), as the keyboard does, and announces it activated (1) after the last.
// Release (position 0) announces it deactivated (0); a slot without a route, or a route that cannot run
// (missing references, a route running itself), is announced as a run error (255). Requests for other
// devices are theirs.
class MemoryFunctions {
public:
    // Runs `work` with an outbox after `delay`, the frames it puts there going out then.
    using Later = std::function<void(std::chrono::milliseconds delay, std::function<void(Outbox&)> work)>;

    MemoryFunctions(const StationLayout& layout, StationState& state, Later later);

    bool handle(const cs2::Message& message, Outbox& out);

    // Routes nest at most this deep (a route running itself stops there).
    static constexpr int MaxDepth = 8;

private:
    // One accessory output switched by a route, `after` the previous one.
    struct Switching {
        std::uint32_t locId = 0;
        std::uint8_t position = 0;
        std::chrono::milliseconds after{0};
    };
    bool expand(std::int64_t route, int depth, std::chrono::milliseconds& carry,
                std::vector<Switching>& out) const;
    Switching switching(std::int64_t keyboardNumber, std::int64_t position) const;
    void run(const cs2::AutomationSwitch& request, std::vector<Switching> steps, Outbox& out);
    void switchNow(const Switching& step, Outbox& out);

    const StationLayout& layout_;
    StationState& state_;
    Later later_;
};

} // namespace stellwerk::sim
