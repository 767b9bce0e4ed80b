#pragma once

#include <cstdint>
#include <optional>

namespace stellwerk::cs2 {

// Conversion between the system speed (0..1000, document chapter 1.3.3) and the speed steps a
// decoder knows. Values 1001..1023 on the wire mean "maximum" and are accepted as such.
class SpeedSteps {
public:
    static constexpr std::uint16_t MaxSystemSpeed = 1000;
    static constexpr std::uint16_t MaxWireSpeed = 1023;

    // 14, 27, 28, 31 or 126 steps; nullopt for any other count.
    static std::optional<SpeedSteps> forStepCount(unsigned steps);

    unsigned stepCount() const { return steps_; }
    unsigned stepWidth() const { return width_; }

    // Track step 0 is standstill; step n maps to 1 + (n - 1) * width, capped at 1000.
    std::uint16_t systemSpeed(unsigned trackStep) const;
    // The track step that a system speed selects; anything from 1000 up is the top step.
    unsigned trackStep(std::uint16_t systemSpeed) const;

private:
    SpeedSteps(unsigned steps, unsigned width) : steps_(steps), width_(width) {}
    unsigned steps_;
    unsigned width_;
};

// A wire speed as a loco sees it: 0..1000, where 1001..1023 count as 1000.
constexpr std::uint16_t effectiveSystemSpeed(std::uint16_t wire) {
    return wire > SpeedSteps::MaxSystemSpeed ? SpeedSteps::MaxSystemSpeed : wire;
}

} // namespace stellwerk::cs2
