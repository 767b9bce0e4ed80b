#include "z21/LocoSpeed.h"

#include "cs2/SpeedSteps.h"

#include <algorithm>

namespace stellwerk::z21 {

namespace {

constexpr std::uint8_t ForwardBit = 0x80;

cs2::SpeedSteps stepsOf(SpeedStepMode mode) {
    return *cs2::SpeedSteps::forStepCount(topStep(mode));
}

// The 5-bit value of 28 steps, V4..V1 then V5: 0/1 stop, 2/3 emergency stop, step n = n + 3.
std::uint8_t code28(std::uint8_t step, bool emergencyStop) {
    const unsigned value = emergencyStop ? 2u : (step == 0 ? 0u : step + 3u);
    return std::uint8_t(((value >> 1) & 0x0F) | ((value & 1u) << 4));
}

LocoSpeed read28(std::uint8_t byte) {
    const unsigned value = ((byte & 0x0Fu) << 1) | ((byte >> 4) & 1u);
    LocoSpeed speed{SpeedStepMode::Steps28, (byte & ForwardBit) != 0, 0, false};
    if (value >= 4)
        speed.step = std::uint8_t(value - 3);
    else
        speed.emergencyStop = value >= 2;
    return speed;
}

// 14 and 128 steps: 0 stop, 1 emergency stop, step n = n + 1 in the low 4 or 7 bits.
LocoSpeed readLinear(SpeedStepMode mode, std::uint8_t byte) {
    const std::uint8_t mask = mode == SpeedStepMode::Steps14 ? 0x0F : 0x7F;
    const std::uint8_t value = byte & mask;
    LocoSpeed speed{mode, (byte & ForwardBit) != 0, 0, value == 1};
    if (value >= 2)
        speed.step = std::uint8_t(value - 1);
    return speed;
}

} // namespace

unsigned topStep(SpeedStepMode mode) {
    switch (mode) {
    case SpeedStepMode::Steps14:
        return 14;
    case SpeedStepMode::Steps28:
        return 28;
    case SpeedStepMode::Steps128:
        break;
    }
    return 126;
}

std::uint8_t speedByte(const LocoSpeed& speed) {
    const std::uint8_t direction = speed.forward ? ForwardBit : 0;
    const auto step = std::uint8_t(std::min<unsigned>(speed.step, topStep(speed.mode)));
    if (speed.mode == SpeedStepMode::Steps28)
        return direction | code28(step, speed.emergencyStop);
    if (speed.emergencyStop)
        return direction | 1;
    return direction | (step == 0 ? 0 : std::uint8_t(step + 1));
}

LocoSpeed speedFromByte(SpeedStepMode mode, std::uint8_t byte) {
    return mode == SpeedStepMode::Steps28 ? read28(byte) : readLinear(mode, byte);
}

std::optional<SpeedStepMode> modeFromDriveCode(std::uint8_t s) {
    switch (s) {
    case 0:
        return SpeedStepMode::Steps14;
    case 2:
        return SpeedStepMode::Steps28;
    case 3:
        return SpeedStepMode::Steps128;
    default:
        return std::nullopt;
    }
}

std::uint8_t driveCode(SpeedStepMode mode) {
    return mode == SpeedStepMode::Steps14 ? 0 : (mode == SpeedStepMode::Steps28 ? 2 : 3);
}

std::optional<SpeedStepMode> modeFromInfoCode(std::uint8_t kkk) {
    switch (kkk) {
    case 0:
        return SpeedStepMode::Steps14;
    case 2:
        return SpeedStepMode::Steps28;
    case 4:
        return SpeedStepMode::Steps128;
    default:
        return std::nullopt;
    }
}

std::uint8_t infoCode(SpeedStepMode mode) {
    return mode == SpeedStepMode::Steps14 ? 0 : (mode == SpeedStepMode::Steps28 ? 2 : 4);
}

std::uint16_t systemSpeed(const LocoSpeed& speed) {
    if (speed.emergencyStop)
        return 0;
    return stepsOf(speed.mode).systemSpeed(speed.step);
}

std::uint8_t stepForSystemSpeed(SpeedStepMode mode, std::uint16_t systemSpeed) {
    return std::uint8_t(stepsOf(mode).trackStep(systemSpeed));
}

} // namespace stellwerk::z21
