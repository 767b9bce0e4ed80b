#include "cs2/SpeedSteps.h"

#include <algorithm>

namespace stellwerk::cs2 {

std::optional<SpeedSteps> SpeedSteps::forStepCount(unsigned steps) {
    switch (steps) {
    case 14:
        return SpeedSteps(14, 77);
    case 27:
        return SpeedSteps(27, 38);
    case 28:
        return SpeedSteps(28, 37);
    case 31:
        return SpeedSteps(31, 33);
    case 126:
        return SpeedSteps(126, 8);
    default:
        return std::nullopt;
    }
}

std::uint16_t SpeedSteps::systemSpeed(unsigned trackStep) const {
    if (trackStep == 0)
        return 0;
    const unsigned step = std::min(trackStep, steps_);
    return std::uint16_t(std::min<unsigned>(1 + (step - 1) * width_, MaxSystemSpeed));
}

unsigned SpeedSteps::trackStep(std::uint16_t systemSpeed) const {
    if (systemSpeed == 0)
        return 0;
    if (systemSpeed >= MaxSystemSpeed)
        return steps_;
    return std::min(1 + (systemSpeed - 1u) / width_, steps_);
}

} // namespace stellwerk::cs2
