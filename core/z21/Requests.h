#pragma once

#include "z21/LocoSpeed.h"

#include <cstdint>
#include <variant>
#include <vector>

namespace stellwerk::z21 {

// The requests a Z21 client sends (Roco's Z21 LAN protocol specification, English v1.10 and later; the
// section numbers below are the specification's). Loco addresses are 14 bits, (Adr_MSB & 0x3F) << 8 |
// Adr_LSB; turnout addresses are the Z21's, counted from 0 (keyboard number = Z21 address + 1, spec 3.3).

// The output format the Z21 keeps per loco or accessory address (3.1, 3.3).
enum class DecoderFormat : std::uint8_t { Dcc = 0, Motorola = 1 };

// What LAN_X_SET_LOCO_FUNCTION does to the function (4.3.1, TT).
enum class FunctionAction : std::uint8_t { Off = 0, On = 1, Toggle = 2 };

struct GetSerialNumber { // 2.1, header 0x10
    bool operator==(const GetSerialNumber&) const = default;
};
struct GetCode { // 2.21, header 0x18
    bool operator==(const GetCode&) const = default;
};
struct GetHardwareInfo { // 2.20, header 0x1A
    bool operator==(const GetHardwareInfo&) const = default;
};
struct Logoff { // 2.2, header 0x30
    bool operator==(const Logoff&) const = default;
};
struct SetBroadcastFlags { // 2.16, header 0x50
    std::uint32_t flags = 0;
    bool operator==(const SetBroadcastFlags&) const = default;
};
struct GetBroadcastFlags { // 2.17, header 0x51
    bool operator==(const GetBroadcastFlags&) const = default;
};
struct GetSystemState { // 2.19, header 0x85
    bool operator==(const GetSystemState&) const = default;
};
struct GetLocoMode { // 3.1, header 0x60
    std::uint16_t address = 0;
    bool operator==(const GetLocoMode&) const = default;
};
struct SetLocoMode { // 3.2, header 0x61
    std::uint16_t address = 0;
    DecoderFormat format = DecoderFormat::Dcc;
    bool operator==(const SetLocoMode&) const = default;
};
struct GetTurnoutMode { // 3.3, header 0x70
    std::uint16_t address = 0;
    bool operator==(const GetTurnoutMode&) const = default;
};
struct SetTurnoutMode { // 3.4, header 0x71
    std::uint16_t address = 0;
    DecoderFormat format = DecoderFormat::Dcc;
    bool operator==(const SetTurnoutMode&) const = default;
};
struct GetXVersion { // 2.3, X 0x21 0x21
    bool operator==(const GetXVersion&) const = default;
};
struct GetXStatus { // 2.4, X 0x21 0x24
    bool operator==(const GetXStatus&) const = default;
};
struct SetTrackPowerOff { // 2.5, X 0x21 0x80
    bool operator==(const SetTrackPowerOff&) const = default;
};
struct SetTrackPowerOn { // 2.6, X 0x21 0x81
    bool operator==(const SetTrackPowerOn&) const = default;
};
struct SetStop { // 2.13, X 0x80: every loco stops, the track power stays on
    bool operator==(const SetStop&) const = default;
};
struct GetFirmwareVersion { // 2.15, X 0xF1 0x0A
    bool operator==(const GetFirmwareVersion&) const = default;
};
struct GetLocoInfo { // 4.1, X 0xE3 0xF0: also subscribes the client to the loco
    std::uint16_t address = 0;
    bool operator==(const GetLocoInfo&) const = default;
};
struct SetLocoDrive { // 4.2, X 0xE4 0x1S
    std::uint16_t address = 0;
    LocoSpeed speed;
    bool operator==(const SetLocoDrive&) const = default;
};
struct SetLocoFunction { // 4.3.1, X 0xE4 0xF8, F0..F31
    std::uint16_t address = 0;
    std::uint8_t function = 0;
    FunctionAction action = FunctionAction::Toggle;
    bool operator==(const SetLocoFunction&) const = default;
};
struct SetLocoEmergencyStop { // 4.5 (v1.13, firmware 1.43), X 0x92
    std::uint16_t address = 0;
    bool operator==(const SetLocoEmergencyStop&) const = default;
};
struct GetTurnoutInfo { // 5.1, X 0x43
    std::uint16_t address = 0;
    bool operator==(const GetTurnoutInfo&) const = default;
};
struct SetTurnout { // 5.2, X 0x53, DB2 = 10Q0A00P
    std::uint16_t address = 0;
    bool secondOutput = false; // P: output 2 (1) or output 1 (0)
    bool activate = false;     // A: switch the output on (1) or off (0)
    bool queue = false;        // Q: queue in the station instead of sending at once
    bool operator==(const SetTurnout&) const = default;
};
// Any packet of a header (and X-header) this codec does not read: the server answers
// LAN_X_UNKNOWN_COMMAND (2.11). The data is kept, at most 64 bytes of it.
struct UnknownRequest {
    std::uint16_t header = 0;
    std::vector<std::uint8_t> data;
    bool operator==(const UnknownRequest&) const = default;
};

using RequestBody = std::variant<GetSerialNumber, GetCode, GetHardwareInfo, Logoff, SetBroadcastFlags,
                                 GetBroadcastFlags, GetSystemState, GetLocoMode, SetLocoMode, GetTurnoutMode,
                                 SetTurnoutMode, GetXVersion, GetXStatus, SetTrackPowerOff, SetTrackPowerOn,
                                 SetStop, GetFirmwareVersion, GetLocoInfo, SetLocoDrive, SetLocoFunction,
                                 SetLocoEmergencyStop, GetTurnoutInfo, SetTurnout, UnknownRequest>;

// One request of a datagram. A wrong XOR byte of an X-bus packet (1.2.2) does not refuse it: some clients
// send wrong ones, so the server answers and counts it.
struct Request {
    RequestBody body;
    bool wrongChecksum = false;
    bool operator==(const Request&) const = default;
};

} // namespace stellwerk::z21
