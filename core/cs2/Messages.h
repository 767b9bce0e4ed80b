#pragma once

#include "cs2/Header.h"
#include "cs2/LocId.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <variant>

namespace stellwerk::cs2 {

class FieldBinder;

// Payload bytes kept as received, for commands whose layout the document leaves open.
struct RawBytes {
    std::uint8_t size = 0;
    std::array<std::uint8_t, 8> bytes{};

    std::span<const std::uint8_t> view() const { return {bytes.data(), size}; }
};

// ---- System commands (0x00, chapter 2) ------------------------------------------------------

// 2.1: track power off on main and programming track; target 0 = every station.
struct SystemStop {
    static constexpr std::string_view name = "system.stop";
    static constexpr Command command = Command::System;
    std::uint32_t target = 0;
    void bind(FieldBinder& b);
};

// 2.2: track power on; stored speeds and functions are sent again.
struct SystemGo {
    static constexpr std::string_view name = "system.go";
    static constexpr Command command = Command::System;
    std::uint32_t target = 0;
    void bind(FieldBinder& b);
};

// 2.3: every loco brakes to 0 with its deceleration; power stays on.
struct SystemHalt {
    static constexpr std::string_view name = "system.halt";
    static constexpr Command command = Command::System;
    std::uint32_t target = 0;
    void bind(FieldBinder& b);
};

// 2.4: emergency stop of one loco that is already in the refresh cycle.
struct LocoEmergencyStop {
    static constexpr std::string_view name = "system.loco-emergency-stop";
    static constexpr Command command = Command::System;
    LocId loco;
    void bind(FieldBinder& b);
};

// 2.5: drop a loco from the refresh cycle; a station UID or 0 clears the whole table.
struct LocoCycleEnd {
    static constexpr std::string_view name = "system.loco-cycle-end";
    static constexpr Command command = Command::System;
    LocId loco;
    void bind(FieldBinder& b);
};

// 2.6: choose the sub-protocol (MM2 frequencies, DCC address length and speed steps) of a loco.
struct LocoProtocol {
    static constexpr std::string_view name = "system.loco-protocol";
    static constexpr Command command = Command::System;
    LocId loco;
    std::uint8_t trackProtocol = 0;
    void bind(FieldBinder& b);
};

// 2.7: default accessory switch time in 10 ms units; 0 restores the default. DLC 5 carries none.
struct AccessorySwitchTime {
    static constexpr std::string_view name = "system.accessory-switch-time";
    static constexpr Command command = Command::System;
    std::uint32_t target = 0;
    std::optional<std::uint16_t> time10ms;
    void bind(FieldBinder& b);
};

// 2.8: lift the wait between mfx read commands for one SID (newer decoders only).
struct MfxFastRead {
    static constexpr std::string_view name = "system.mfx-fast-read";
    static constexpr Command command = Command::System;
    std::uint32_t sender = 0;
    std::uint16_t sid = 0;
    void bind(FieldBinder& b);
};

// 2.9: enable (bit set) or block track protocols: bit 0 MM2, bit 1 mfx, bit 2 DCC.
struct TrackProtocols {
    static constexpr std::string_view name = "system.track-protocols";
    static constexpr Command command = Command::System;
    std::uint32_t target = 0;
    std::uint8_t mask = 0;
    void bind(FieldBinder& b);
};

// 2.10: set the mfx re-registration counter of a station.
struct MfxRegistrationCounter {
    static constexpr std::string_view name = "system.mfx-registration-counter";
    static constexpr Command command = Command::System;
    std::uint32_t target = 0;
    std::uint16_t counter = 0;
    void bind(FieldBinder& b);
};

// 2.11: a station reports an overload on one of its channels (response only).
struct Overload {
    static constexpr std::string_view name = "system.overload";
    static constexpr Command command = Command::System;
    std::uint32_t sender = 0;
    std::uint8_t channel = 0;
    void bind(FieldBinder& b);
};

// 2.12: read a measurement channel (DLC 6), set a configuration value (DLC 8), its acknowledgement
// (DLC 7, accepted or not) and the reading itself (DLC 8 response).
struct SystemStatus {
    static constexpr std::string_view name = "system.status";
    static constexpr Command command = Command::System;
    std::uint32_t device = 0;
    std::uint8_t channel = 0;
    std::optional<std::uint16_t> value;
    std::optional<bool> accepted;
    void bind(FieldBinder& b);
};

// 2.13: ask for (DLC 5) or assign (DLC 7) the 16-bit device id used in feedback and automation ids.
struct DeviceId {
    static constexpr std::string_view name = "system.device-id";
    static constexpr Command command = Command::System;
    std::uint32_t target = 0;
    std::optional<std::uint16_t> deviceId;
    void bind(FieldBinder& b);
};

// 2.14: reset a device; 0xFF is the only target value seen in the wild.
struct SystemReset {
    static constexpr std::string_view name = "system.reset";
    static constexpr Command command = Command::System;
    std::uint32_t target = 0;
    std::uint8_t resetTarget = 0;
    void bind(FieldBinder& b);
};

// System 0x30: low-level mfx answer handling (wait for a bit or N bytes, answers with index/value).
struct MfxSeek {
    static constexpr std::string_view name = "system.mfx-seek";
    static constexpr Command command = Command::System;
    std::uint32_t target = 0;
    std::uint8_t code = 0;
    std::optional<std::uint8_t> argument;
    std::optional<std::uint8_t> answer;
    void bind(FieldBinder& b);
};

// ---- Management (chapter 3) ------------------------------------------------------------------

// 3.1: find locos on the track: all protocols (DLC 0), by protocol (DLC 1), one mfx range step or
// address probe (DLC 5), debug answer with ASK ratio (DLC 6).
struct LocoDiscovery {
    static constexpr std::string_view name = "loco.discovery";
    static constexpr Command command = Command::LocoDiscovery;
    std::optional<std::uint32_t> uid;
    std::optional<std::uint8_t> range;
    std::optional<std::uint8_t> ask;
    void bind(FieldBinder& b);
};

// 3.2: give an mfx decoder (by its UID) a session id (SID).
struct MfxBind {
    static constexpr std::string_view name = "mfx.bind";
    static constexpr Command command = Command::MfxBind;
    std::uint32_t mfxUid = 0;
    std::uint16_t sid = 0;
    void bind(FieldBinder& b);
};

// 3.3: check that a decoder answers under UID + SID; the positive answer carries the ASK ratio.
struct MfxVerify {
    static constexpr std::string_view name = "mfx.verify";
    static constexpr Command command = Command::MfxVerify;
    std::uint32_t mfxUid = 0;
    std::uint16_t sid = 0;
    std::optional<std::uint8_t> ask;
    void bind(FieldBinder& b);
};

// 3.4: set (DLC 6) or query (DLC 4) a loco's system speed 0..1000 (1023 at most).
struct LocoSpeed {
    static constexpr std::string_view name = "loco.speed";
    static constexpr Command command = Command::LocoSpeed;
    LocId loco;
    std::optional<std::uint16_t> speed;
    void bind(FieldBinder& b);
};

// Direction values of 3.5. Values above 3 are kept as received and mean "keep".
enum class Direction : std::uint8_t { Keep = 0, Forward = 1, Backward = 2, Toggle = 3 };

// 3.5: set (DLC 5) or query (DLC 4) the direction.
struct LocoDirection {
    static constexpr std::string_view name = "loco.direction";
    static constexpr Command command = Command::LocoDirection;
    LocId loco;
    std::optional<std::uint8_t> direction;
    void bind(FieldBinder& b);
};

// 3.6: query (DLC 5), set (DLC 6) or set with a 16-bit function value (DLC 8) one of F0..F31.
struct LocoFunction {
    static constexpr std::string_view name = "loco.function";
    static constexpr Command command = Command::LocoFunction;
    LocId loco;
    std::uint8_t function = 0;
    std::optional<std::uint8_t> value;
    std::optional<std::uint16_t> functionValue;
    void bind(FieldBinder& b);
};

// CV address of 3.7/3.8: 6-bit index (mfx only) and 10-bit CV number packed into two bytes.
struct CvAddress {
    std::uint16_t number = 0;
    std::uint8_t index = 0;

    static constexpr CvAddress unpack(std::uint16_t packed) {
        return {std::uint16_t(packed & 0x03FF), std::uint8_t(packed >> 10)};
    }
    constexpr std::uint16_t packed() const { return std::uint16_t((index << 10) | (number & 0x03FF)); }
};

// 3.7: read CVs: the request names how many bytes (0 = 256); each answer carries one byte;
// an answer without a value byte (DLC 6) reports that nothing could be read.
struct ConfigRead {
    static constexpr std::string_view name = "config.read";
    static constexpr Command command = Command::ConfigRead;
    LocId loco;
    CvAddress cv;
    std::optional<std::uint8_t> count; // request form
    std::optional<std::uint8_t> value; // response form
    void bind(FieldBinder& b);
};

// DCC programming modes of 3.8 (control bits 5 and 4).
enum class DccProgrammingMode : std::uint8_t { Direct = 0, Register = 1, Bit = 2, Reserved = 3 };

// 3.8: write one CV. The last byte is the control byte in a request (main track, multi-byte,
// DCC mode) and the result byte in the answer (write confirmed, verify succeeded).
struct ConfigWrite {
    static constexpr std::string_view name = "config.write";
    static constexpr Command command = Command::ConfigWrite;
    static constexpr std::uint8_t MainTrack = 0x80;
    static constexpr std::uint8_t MultiByte = 0x40;
    static constexpr std::uint8_t WriteOk = 0x80;
    static constexpr std::uint8_t VerifyOk = 0x40;

    LocId loco;
    CvAddress cv;
    std::uint8_t value = 0;
    std::uint8_t flags = 0;

    DccProgrammingMode mode() const { return DccProgrammingMode((flags >> 4) & 0x03); }
    void bind(FieldBinder& b);
};

// ---- Accessories (chapter 4) -----------------------------------------------------------------

// 4.1: switch an accessory output; DLC 8 adds a switch time (10 ms units) or special value.
struct AccessorySwitch {
    static constexpr std::string_view name = "accessory.switch";
    static constexpr Command command = Command::AccessorySwitch;
    LocId article;
    std::uint8_t position = 0;
    std::uint8_t current = 0;
    std::optional<std::uint16_t> time10ms;
    void bind(FieldBinder& b);
};

// 0x0C: accessory configuration; named in the document's table, its layout is unpublished.
struct AccessoryConfig {
    static constexpr std::string_view name = "accessory.config";
    static constexpr Command command = Command::AccessoryConfig;
    RawBytes raw;
    void bind(FieldBinder& b);
};

// ---- Feedback (chapter 5) --------------------------------------------------------------------

// 5.1: legacy S88 register polling: request (DLC 5, module count), one answer per module (DLC 7).
struct S88Poll {
    static constexpr std::string_view name = "feedback.s88-poll";
    static constexpr Command command = Command::S88Poll;
    std::uint32_t device = 0;
    std::optional<std::uint8_t> moduleCount;
    std::optional<std::uint8_t> module;
    std::optional<std::uint16_t> state;
    void bind(FieldBinder& b);
};

// Old/new state and time (10 ms units) of an S88 event answer.
struct S88Change {
    std::uint8_t oldState = 0;
    std::uint8_t newState = 0;
    std::uint16_t time10ms = 0;
};

// 5.2: query a contact (DLC 4), register it with a parameter (DLC 5), register a block of contacts
// (DLC 7), or the event/answer with old and new state (DLC 8).
struct S88Event {
    static constexpr std::string_view name = "feedback.s88-event";
    static constexpr Command command = Command::S88Event;
    std::uint16_t device = 0;
    std::uint16_t contact = 0;
    std::optional<std::uint16_t> lastContact;
    std::optional<std::uint8_t> parameter;
    std::optional<S88Change> change;
    void bind(FieldBinder& b);
};

// 0x12: a Selectrix feedback address and, in the DLC 6 form, its state.
struct Sx1Event {
    static constexpr std::string_view name = "feedback.sx1-event";
    static constexpr Command command = Command::Sx1Event;
    std::uint32_t uid = 0;
    std::uint8_t address = 0;
    std::optional<std::uint8_t> state;
    void bind(FieldBinder& b);
};

// ---- Other commands (chapter 6) --------------------------------------------------------------

// Who answered a ping: UID, software version major.minor and device type.
struct DeviceIdentity {
    std::uint32_t uid = 0;
    std::uint8_t versionMajor = 0;
    std::uint8_t versionMinor = 0;
    std::uint16_t deviceType = 0;
};

std::string_view deviceTypeName(std::uint16_t deviceType);

// 6.1: ask every device (DLC 0); each answers with its identity (DLC 8).
struct Ping {
    static constexpr std::string_view name = "ping";
    static constexpr Command command = Command::Ping;
    std::optional<DeviceIdentity> identity;
    void bind(FieldBinder& b);
};

// 0x19: firmware update offer (DLC 8); layout unpublished.
struct UpdateOffer {
    static constexpr std::string_view name = "update.offer";
    static constexpr Command command = Command::UpdateOffer;
    RawBytes raw;
    void bind(FieldBinder& b);
};

// 0x1A: read config data of the update machinery (DLC 4 or 8); layout unpublished.
struct ReadConfigData {
    static constexpr std::string_view name = "update.read-config-data";
    static constexpr Command command = Command::ReadConfigData;
    RawBytes raw;
    void bind(FieldBinder& b);
};

// 0x1B: CAN bootloader of MS2, Gleisbox and Link S88: query (DLC 0), identity answer (DLC 8
// response), command code (DLC 5, 0x11 = start application), block select (DLC 6), block CRC
// (DLC 7), block data (DLC 8 request, hash = packet number).
struct BootloaderCan {
    static constexpr std::string_view name = "bootloader.can";
    static constexpr Command command = Command::BootloaderCan;
    RawBytes raw;
    void bind(FieldBinder& b);
};

// 0x1C: track-bound bootloader (DLC 4..8); layout unpublished, decoded as UID + bytes.
struct BootloaderTrack {
    static constexpr std::string_view name = "bootloader.track";
    static constexpr Command command = Command::BootloaderTrack;
    RawBytes raw;
    void bind(FieldBinder& b);
};

// 6.2: status data configuration: request one index of a device (DLC 5), the answer's data
// packets (response, hash = packet number), and the end frame (response, DLC 6 with the packet
// count; DLC 5 without it from some devices).
struct StatusDataConfig {
    static constexpr std::string_view name = "statusdata.config";
    static constexpr Command command = Command::StatusDataConfig;
    enum class Form : std::uint8_t { Request, Packet, End };

    Form form = Form::Request;
    std::uint32_t device = 0;
    std::uint8_t index = 0;
    std::optional<std::uint8_t> packetCount;
    RawBytes packet;
    void bind(FieldBinder& b);
};

// ---- GUI information transfer (chapter 7) ----------------------------------------------------

// 7.1: ask for a configuration file by its 8-byte key ("loks", "gbs-2", ...), zero padded.
struct ConfigDataRequest {
    static constexpr std::string_view name = "configdata.request";
    static constexpr Command command = Command::ConfigDataRequest;
    std::array<char, 8> filename{};

    std::string_view text() const; // up to the first NUL
    void bind(FieldBinder& b);
};

// 7.2: a config data stream frame: header (DLC 6: length + CRC), broadcast header (DLC 7: plus one
// byte), or eight data bytes (DLC 8).
struct ConfigDataStream {
    static constexpr std::string_view name = "configdata.stream";
    static constexpr Command command = Command::ConfigDataStream;
    enum class Form : std::uint8_t { Header, BroadcastHeader, Data };

    Form form = Form::Data;
    std::uint32_t length = 0;
    std::uint16_t crc = 0;
    std::uint8_t extra = 0;
    std::array<std::uint8_t, 8> data{};
    void bind(FieldBinder& b);
};

// 0x22: Connect 6021 (60128) data stream: UID, then one byte (DLC 5) or a 16-bit value (DLC 6).
struct Connect6021Stream {
    static constexpr std::string_view name = "connect6021.stream";
    static constexpr Command command = Command::Connect6021Stream;
    RawBytes raw;
    void bind(FieldBinder& b);
};

// ---- Automation (chapter 9) ------------------------------------------------------------------

// 9.1: trigger a memory/automation function (DLC 6: position and parameter), its status answer
// (DLC 6 response), or the loco assigned to a block (DLC 8).
struct AutomationSwitch {
    static constexpr std::string_view name = "automation.switch";
    static constexpr Command command = Command::AutomationSwitch;
    std::uint16_t device = 0;
    std::uint16_t function = 0;
    std::uint8_t position = 0;  // request: position; response: status
    std::uint8_t parameter = 0; // DLC 6 form
    std::optional<LocId> loco;  // DLC 8 form
    void bind(FieldBinder& b);
};

// Anything else: the command number and the bytes, never a crash.
struct Unknown {
    static constexpr std::string_view name = "unknown";
    std::uint8_t command = 0;
    RawBytes raw;
    void bind(FieldBinder& b);
};

using MessageBody =
    std::variant<Unknown, SystemStop, SystemGo, SystemHalt, LocoEmergencyStop, LocoCycleEnd, LocoProtocol,
                 AccessorySwitchTime, MfxFastRead, TrackProtocols, MfxRegistrationCounter, Overload,
                 SystemStatus, DeviceId, SystemReset, MfxSeek, LocoDiscovery, MfxBind, MfxVerify, LocoSpeed,
                 LocoDirection, LocoFunction, ConfigRead, ConfigWrite, AccessorySwitch, AccessoryConfig,
                 S88Poll, S88Event, Sx1Event, Ping, UpdateOffer, ReadConfigData, BootloaderCan,
                 BootloaderTrack, StatusDataConfig, ConfigDataRequest, ConfigDataStream, Connect6021Stream,
                 AutomationSwitch>;

// A decoded CS2 message: the frame header fields plus the typed body.
struct Message {
    std::uint8_t prio = 0;
    bool response = false;
    std::uint16_t hash = 0;
    MessageBody body;
};

std::string_view messageName(const MessageBody& body);

// The system sub-command byte of a body, if it is a system command.
std::optional<std::uint8_t> systemSubcommand(const MessageBody& body);

} // namespace stellwerk::cs2
