#pragma once

#include <cstdint>
#include <optional>

namespace stellwerk::z21 {

// The speed steps a Z21 loco command names: S in 0x1S of LAN_X_SET_LOCO_DRIVE (spec 4.2) and KKK of
// LAN_X_LOCO_INFO (4.4) count them differently, so each has its own conversion below.
enum class SpeedStepMode : std::uint8_t { Steps14, Steps28, Steps128 };

// The highest step of a mode: 14, 28, or 126 (the 128-step mode has 126 driving steps).
unsigned topStep(SpeedStepMode mode);

// A loco's direction and speed as a Z21 byte RVVVVVVV carries it (spec 4.2): step 0 is stop, an emergency
// stop has step 0, and a step above the mode's top is sent as the top step.
struct LocoSpeed {
    SpeedStepMode mode = SpeedStepMode::Steps128;
    bool forward = true;
    std::uint8_t step = 0;
    bool emergencyStop = false;

    bool operator==(const LocoSpeed&) const = default;
};

// RVVVVVVV of a speed: R = forward; the speed code of the mode (4.2's three tables; 28 steps carry the
// step's lowest bit in bit 4, "V5").
std::uint8_t speedByte(const LocoSpeed& speed);
// The speed a byte RVVVVVVV means in a mode. Both stop and both emergency stop codes of 28 steps are read.
LocoSpeed speedFromByte(SpeedStepMode mode, std::uint8_t byte);

// S of 0x1S in LAN_X_SET_LOCO_DRIVE: 0, 2 or 3; nullopt for any other.
std::optional<SpeedStepMode> modeFromDriveCode(std::uint8_t s);
std::uint8_t driveCode(SpeedStepMode mode);
// KKK of LAN_X_LOCO_INFO: 0, 2 or 4; nullopt for any other.
std::optional<SpeedStepMode> modeFromInfoCode(std::uint8_t kkk);
std::uint8_t infoCode(SpeedStepMode mode);

// The one place where Z21 steps meet the station's speed 0..1000 (CS2 chapter 1.3.3), through the CS2
// codec's step table: step n of 14, 28 or 126 is the station speed that step selects; an emergency stop is 0.
std::uint16_t systemSpeed(const LocoSpeed& speed);
// The step of a mode that a station speed 0..1000 selects (anything from 1000 up is the top step).
std::uint8_t stepForSystemSpeed(SpeedStepMode mode, std::uint16_t systemSpeed);

} // namespace stellwerk::z21
