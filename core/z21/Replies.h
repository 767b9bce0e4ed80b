#pragma once

#include "z21/LocoSpeed.h"
#include "z21/Requests.h"

#include <cstdint>
#include <variant>

namespace stellwerk::z21 {

// What a Z21 server sends: the answers to requests and the broadcasts (Roco's Z21 LAN protocol
// specification, English v1.10 and later; section numbers are the specification's).

// Central state bits (2.12, 2.18) and extended central state bits (2.18).
namespace central {
inline constexpr std::uint8_t EmergencyStop = 0x01;
inline constexpr std::uint8_t TrackVoltageOff = 0x02;
inline constexpr std::uint8_t ShortCircuit = 0x04;
inline constexpr std::uint8_t ProgrammingModeActive = 0x20;
inline constexpr std::uint8_t HighTemperature = 0x01; // CentralStateEx
inline constexpr std::uint8_t PowerLost = 0x02;       // CentralStateEx
inline constexpr std::uint8_t ShortCircuitExternal = 0x04;
inline constexpr std::uint8_t ShortCircuitInternal = 0x08;
} // namespace central

// Broadcast flags of LAN_SET_BROADCASTFLAGS (2.16) a server of locos and turnouts acts on.
namespace broadcast {
inline constexpr std::uint32_t DrivingAndSwitching = 0x00000001;
inline constexpr std::uint32_t SystemState = 0x00000100;
inline constexpr std::uint32_t AllLocos = 0x00010000;
} // namespace broadcast

// Hardware types of LAN_GET_HWINFO (2.20).
inline constexpr std::uint32_t HardwareZ21New = 0x00000201;

// A firmware version as the BCD the specification writes (2.15, 2.20): 1.43 -> 0x0143.
constexpr std::uint16_t bcdVersion(unsigned major, unsigned minor) {
    return std::uint16_t(((major / 10) << 12) | ((major % 10) << 8) | ((minor / 10) << 4) | (minor % 10));
}

struct SerialNumber { // 2.1
    std::uint32_t serial = 0;
    bool operator==(const SerialNumber&) const = default;
};
struct FeatureCode { // 2.21: 0x00 nothing locked (what every client accepts)
    std::uint8_t code = 0;
    bool operator==(const FeatureCode&) const = default;
};
struct HardwareInfo { // 2.20: type and firmware (BCD, little endian)
    std::uint32_t hardwareType = HardwareZ21New;
    std::uint32_t firmware = bcdVersion(1, 43);
    bool operator==(const HardwareInfo&) const = default;
};
struct BroadcastFlags { // 2.17
    std::uint32_t flags = 0;
    bool operator==(const BroadcastFlags&) const = default;
};
// 2.18 LAN_SYSTEMSTATE_DATACHANGED: currents in mA, temperature in °C, voltages in mV.
struct SystemState {
    std::int16_t mainCurrent = 0;
    std::int16_t programmingCurrent = 0;
    std::int16_t filteredMainCurrent = 0;
    std::int16_t temperature = 0;
    std::uint16_t supplyVoltage = 0;
    std::uint16_t trackVoltage = 0; // VCCVoltage, "identical to the track voltage"
    std::uint8_t centralState = 0;
    std::uint8_t centralStateEx = 0;
    std::uint8_t capabilities = 0; // from firmware 1.42; 0 = not told
    bool operator==(const SystemState&) const = default;
};
struct LocoMode { // 3.1
    std::uint16_t address = 0;
    DecoderFormat format = DecoderFormat::Dcc;
    bool operator==(const LocoMode&) const = default;
};
struct TurnoutMode { // 3.3
    std::uint16_t address = 0;
    DecoderFormat format = DecoderFormat::Dcc;
    bool operator==(const TurnoutMode&) const = default;
};
struct XVersion { // 2.3: X-bus version 3.0, command station 0x12 (the Z21 family)
    std::uint8_t xBusVersion = 0x30;
    std::uint8_t commandStationId = 0x12;
    bool operator==(const XVersion&) const = default;
};
struct XStatusChanged { // 2.12: the central state bits
    std::uint8_t centralState = 0;
    bool operator==(const XStatusChanged&) const = default;
};
struct TrackPowerOff { // 2.7
    bool operator==(const TrackPowerOff&) const = default;
};
struct TrackPowerOn { // 2.8
    bool operator==(const TrackPowerOn&) const = default;
};
struct ProgrammingMode { // 2.9
    bool operator==(const ProgrammingMode&) const = default;
};
struct TrackShortCircuit { // 2.10
    bool operator==(const TrackShortCircuit&) const = default;
};
struct UnknownCommand { // 2.11
    bool operator==(const UnknownCommand&) const = default;
};
struct Stopped { // 2.14
    bool operator==(const Stopped&) const = default;
};
struct FirmwareVersion { // 2.15, BCD
    std::uint16_t version = bcdVersion(1, 43);
    bool operator==(const FirmwareVersion&) const = default;
};
// 4.4 LAN_X_LOCO_INFO, always with DB8 (F29..F31): functions bit n = Fn.
struct LocoInfo {
    std::uint16_t address = 0;
    bool busy = false; // driven by another throttle
    LocoSpeed speed;
    std::uint32_t functions = 0;
    bool doubleTraction = false;
    bool smartSearch = false;
    bool operator==(const LocoInfo&) const = default;
};
// 5.3 LAN_X_TURNOUT_INFO: which output was switched last (ZZ).
enum class TurnoutPosition : std::uint8_t { NotSwitched = 0, Output1 = 1, Output2 = 2, Invalid = 3 };
struct TurnoutInfo {
    std::uint16_t address = 0;
    TurnoutPosition position = TurnoutPosition::NotSwitched;
    bool operator==(const TurnoutInfo&) const = default;
};

using Reply =
    std::variant<SerialNumber, FeatureCode, HardwareInfo, BroadcastFlags, SystemState, LocoMode, TurnoutMode,
                 XVersion, XStatusChanged, TrackPowerOff, TrackPowerOn, ProgrammingMode, TrackShortCircuit,
                 UnknownCommand, Stopped, FirmwareVersion, LocoInfo, TurnoutInfo>;

} // namespace stellwerk::z21
