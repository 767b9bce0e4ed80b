#pragma once

#include "orc/OrcId.h"

#include <array>
#include <cstdint>
#include <string_view>
#include <variant>
#include <vector>

namespace stellwerk::orc {

// The sender of a frame, from its identifier: priority (0 when encoding = the message's default, notes
// A1.4), device type (0..3) and bus id. Group and direction are fixed by the message type, or carried by
// the message where the document lets both directions occur.
struct Origin {
    std::uint8_t prio = 0;
    std::uint8_t type = 0;
    std::uint16_t busId = 0;
    friend constexpr bool operator==(const Origin&, const Origin&) = default;
};

// Whom a system command is for: everybody (DLC 1), one bus id ("Ziel-Id", DLC 3) or one UID (DLC 5).
struct Target {
    enum class Kind : std::uint8_t { All, BusId, Uid };
    Kind kind = Kind::All;
    std::uint32_t value = 0;
    static constexpr Target all() { return {}; }
    static constexpr Target busId(std::uint16_t id) { return {Kind::BusId, id}; }
    static constexpr Target uid(std::uint32_t uid) { return {Kind::Uid, uid}; }
    friend constexpr bool operator==(const Target&, const Target&) = default;
};

// Up to eight bytes kept as received, for frames the codec does not understand.
struct Bytes {
    std::uint8_t size = 0;
    std::array<std::uint8_t, 8> data{};
    friend constexpr bool operator==(const Bytes&, const Bytes&) = default;
};

// ---- 0x80 System (001 §Befehlssatz System; every device) --------------------------------------------------

// #1-#3 Alles Aus: the whole system, one device or one UID without power ("Stromlos").
struct AllOff {
    static constexpr std::string_view name = "orc.system.allOff";
    Origin from;
    Target target;
    friend constexpr bool operator==(const AllOff&, const AllOff&) = default;
};

// #4-#6 Alles EIN: "gültige" devices may switch their outputs again.
struct AllOn {
    static constexpr std::string_view name = "orc.system.allOn";
    Origin from;
    Target target;
    friend constexpr bool operator==(const AllOn&, const AllOn&) = default;
};

// #7/#8 Überlast: kind 0 none (cleared), 1 current, 2 temperature; DLC 3 names the port. An event: the
// document prints D=0, Stellwerk accepts either (notes O20).
struct Overload {
    static constexpr std::string_view name = "orc.system.overload";
    Origin from;
    bool answer = false;
    std::uint8_t kind = 0;
    bool hasPort = false;
    std::uint8_t port = 0;
    friend constexpr bool operator==(const Overload&, const Overload&) = default;
};

// ---- 0x81 Lok Control (boosters and throttles)
// -------------------------------------------------------------

// #9-#11 Lok(s) Nothalt: all locos, one Ziel-Id or one UID.
struct LocoStop {
    static constexpr std::string_view name = "orc.loco.stop";
    Origin from;
    Target target;
    friend constexpr bool operator==(const LocoStop&, const LocoStop&) = default;
};

// #12: speed of loco Ziel-Id asked for.
struct LocoSpeedQuery {
    static constexpr std::string_view name = "orc.loco.speedQuery";
    Origin from;
    std::uint16_t target = 0;
    friend constexpr bool operator==(const LocoSpeedQuery&, const LocoSpeedQuery&) = default;
};

// #13: D=0 sets the speed, D=1 is the loco's answer. Speed u16: 0..1000 in bits 0-14, bit 15 reverse
// (Stellwerk's extension, notes O13).
struct LocoSpeed {
    static constexpr std::string_view name = "orc.loco.speed";
    Origin from;
    bool answer = false;
    std::uint16_t target = 0;
    std::uint16_t speed = 0;
    friend constexpr bool operator==(const LocoSpeed&, const LocoSpeed&) = default;
};

// #15: speed of the loco with this UID asked for.
struct LocoSpeedQueryByUid {
    static constexpr std::string_view name = "orc.loco.speedQueryUid";
    Origin from;
    std::uint32_t uid = 0;
    friend constexpr bool operator==(const LocoSpeedQueryByUid&, const LocoSpeedQueryByUid&) = default;
};

// #16 (and #14, the text-only form under sub-code 0x01, kept as `textForm` so the frame reads back as sent;
// Stellwerk encodes new messages with 0x02, notes O14).
struct LocoSpeedByUid {
    static constexpr std::string_view name = "orc.loco.speedUid";
    Origin from;
    bool answer = false;
    std::uint32_t uid = 0;
    std::uint16_t speed = 0;
    bool textForm = false;
    friend constexpr bool operator==(const LocoSpeedByUid&, const LocoSpeedByUid&) = default;
};

// #17: the state of all functions asked for.
struct LocoFunctionsQuery {
    static constexpr std::string_view name = "orc.loco.functionsQuery";
    Origin from;
    std::uint16_t target = 0;
    friend constexpr bool operator==(const LocoFunctionsQuery&, const LocoFunctionsQuery&) = default;
};

// #18: "Status für Fx0 bis Fx31", u32 big endian, bit n = Fn (notes O16); D=0 sets, D=1 answers.
struct LocoFunctions {
    static constexpr std::string_view name = "orc.loco.functions";
    Origin from;
    bool answer = false;
    std::uint16_t target = 0;
    std::uint32_t functions = 0;
    friend constexpr bool operator==(const LocoFunctions&, const LocoFunctions&) = default;
};

// #19: one function asked for (DLC 4 as in the table; the text's DLC 3 has no room for FxNr).
struct LocoFunctionQuery {
    static constexpr std::string_view name = "orc.loco.functionQuery";
    Origin from;
    std::uint16_t target = 0;
    std::uint8_t function = 0;
    friend constexpr bool operator==(const LocoFunctionQuery&, const LocoFunctionQuery&) = default;
};

// #20: one function set (D=0) or answered (D=1); Wert 0 = off, others decoder-specific. Sent with DLC 7
// (DB6-7 zero) as printed; DLC 5 and 6 are accepted and kept (notes O15).
struct LocoFunction {
    static constexpr std::string_view name = "orc.loco.function";
    Origin from;
    bool answer = false;
    std::uint16_t target = 0;
    std::uint8_t function = 0;
    std::uint8_t value = 0;
    std::uint8_t dlc = 7;
    friend constexpr bool operator==(const LocoFunction&, const LocoFunction&) = default;
};

// ---- 0x88 Dekoder (stationary outputs)
// ----------------------------------------------------------------------

// #21-#23: all decoders off, on, or back to their last known position.
enum class GroupAction : std::uint8_t { Off = 0x00, On = 0x01, Restore = 0x02 };

struct AllDecoders {
    static constexpr std::string_view name = "orc.decoder.all";
    Origin from;
    GroupAction action = GroupAction::Off;
    friend constexpr bool operator==(const AllDecoders&, const AllDecoders&) = default;
};

// #24 dekoder schalten: outputs of Ziel-Id to Pos (decoder-specific; for MM/DCC turnouts 0 = round/red,
// 1 = straight/green). D=1 is the decoder's optional acknowledgement.
struct DecoderSwitch {
    static constexpr std::string_view name = "orc.decoder.switch";
    Origin from;
    bool answer = false;
    std::uint16_t target = 0;
    std::uint8_t position = 0;
    friend constexpr bool operator==(const DecoderSwitch&, const DecoderSwitch&) = default;
};

// ---- 0x89 Enkoder (inputs)
// ----------------------------------------------------------------------------------

// #25-#27: all encoders off, on (inputs at their default) or restored (from their stored state).
struct AllEncoders {
    static constexpr std::string_view name = "orc.encoder.all";
    Origin from;
    GroupAction action = GroupAction::Off;
    friend constexpr bool operator==(const AllEncoders&, const AllEncoders&) = default;
};

// #28 enkoder Abfrage: encoder Ziel-Id asked for its inputs (DLC 3); the printed DLC 1 reads as "every
// encoder" (notes O18).
struct EncoderQuery {
    static constexpr std::string_view name = "orc.encoder.query";
    Origin from;
    bool everyEncoder = false;
    std::uint16_t target = 0;
    friend constexpr bool operator==(const EncoderQuery&, const EncoderQuery&) = default;
};

// #29 enkoder Status: inputs 0..8*bytes-1 of the encoder whose id is in DB2-3; input n = bit (n mod 8) of
// DB(4 + n/8) (notes A3.5), kept here as bit n of `inputs`. D=1 answers a query, D=0 is an event.
struct EncoderStatus {
    static constexpr std::string_view name = "orc.encoder.status";
    Origin from;
    bool answer = false;
    std::uint16_t encoder = 0;
    std::uint8_t bytes = 4; // 1..4 status bytes: 8, 16, 24 or 32 inputs
    std::uint32_t inputs = 0;
    friend constexpr bool operator==(const EncoderStatus&, const EncoderStatus&) = default;
};

// ---- 0x90 System Management
// ---------------------------------------------------------------------------------

// #30: is the device with this UID there?
struct Ping {
    static constexpr std::string_view name = "orc.mgmt.ping";
    Origin from;
    std::uint32_t uid = 0;
    friend constexpr bool operator==(const Ping&, const Ping&) = default;
};

// #31: present, with its software version (u16, shown hi.lo).
struct PingAnswer {
    static constexpr std::string_view name = "orc.mgmt.pingAnswer";
    Origin from;
    std::uint32_t uid = 0;
    std::uint16_t version = 0;
    friend constexpr bool operator==(const PingAnswer&, const PingAnswer&) = default;
};

// #32 Find: look for new devices. DB2-5 are unlabelled; Stellwerk sends 0 = "any unregistered device".
struct Find {
    static constexpr std::string_view name = "orc.mgmt.find";
    Origin from;
    std::uint32_t uid = 0;
    friend constexpr bool operator==(const Find&, const Find&) = default;
};

// EXTENSION (Stellwerk, notes A3.2): the answer to Find the document does not define; mirrors the Ping
// answer (sub 0x01, D=1, DLC 7: UID, version).
struct FindAnswer {
    static constexpr std::string_view name = "orc.mgmt.findAnswer";
    Origin from;
    std::uint32_t uid = 0;
    std::uint16_t version = 0;
    friend constexpr bool operator==(const FindAnswer&, const FindAnswer&) = default;
};

// EXTENSION (Stellwerk, notes A3.2): the central gives the device with this UID a new bus id (sub 0x02,
// D=0, DLC 7); the device confirms with the same bytes and D=1, sent from its new bus id.
struct AssignBusId {
    static constexpr std::string_view name = "orc.mgmt.assign";
    Origin from;
    bool answer = false;
    std::uint32_t uid = 0;
    std::uint16_t busId = 0;
    friend constexpr bool operator==(const AssignBusId&, const AssignBusId&) = default;
};

// ---- 0xF0 Programm Flash (sub-codes from the headings: Size 0x02, Checksum 0x05, notes O12)
// ----------------

// #33: every flash process is cancelled.
struct FlashCancel {
    static constexpr std::string_view name = "orc.flash.cancel";
    Origin from;
    friend constexpr bool operator==(const FlashCancel&, const FlashCancel&) = default;
};

// #34/#35: enter flash mode; the target by bus id (DLC 4) or UID (DLC 6), Vers u8.
struct FlashInit {
    static constexpr std::string_view name = "orc.flash.init";
    Origin from;
    Target target = Target::busId(0);
    std::uint8_t version = 0;
    friend constexpr bool operator==(const FlashInit&, const FlashInit&) = default;
};

// #36 Flash Acceppted: bus id, UID and the version now in the device.
struct FlashAccepted {
    static constexpr std::string_view name = "orc.flash.accepted";
    Origin from;
    std::uint16_t target = 0;
    std::uint32_t uid = 0;
    std::uint8_t version = 0;
    friend constexpr bool operator==(const FlashAccepted&, const FlashAccepted&) = default;
};

// #37: start address (u24, DB4-6) and byte count (u16, DB7-8): Stellwerk's split of the 5 bytes (A3.7).
// `tableCode` = the frame carried the table's sub-code 0x01 (read, never chosen by Stellwerk).
struct FlashSize {
    static constexpr std::string_view name = "orc.flash.size";
    Origin from;
    std::uint16_t target = 0;
    std::uint32_t start = 0;
    std::uint16_t size = 0;
    bool tableCode = false;
    friend constexpr bool operator==(const FlashSize&, const FlashSize&) = default;
};

// #38: bytes available (u16) and transfers per cycle (CntMax u8).
struct FlashSizeAnswer {
    static constexpr std::string_view name = "orc.flash.sizeAnswer";
    Origin from;
    std::uint16_t target = 0;
    std::uint16_t available = 0;
    std::uint8_t countMax = 0;
    bool tableCode = false;
    friend constexpr bool operator==(const FlashSizeAnswer&, const FlashSizeAnswer&) = default;
};

// #39/#40: four bytes with their counter; the device echoes them with D=1.
struct FlashData {
    static constexpr std::string_view name = "orc.flash.data";
    Origin from;
    bool answer = false;
    std::uint16_t target = 0;
    std::uint8_t count = 0;
    std::array<std::uint8_t, 4> bytes{};
    friend constexpr bool operator==(const FlashData&, const FlashData&) = default;
};

// #41/#42: the cycle's CRC (CRC-32/IEEE, Stellwerk's choice); the device answers with counter 0.
struct FlashChecksum {
    static constexpr std::string_view name = "orc.flash.checksum";
    Origin from;
    bool answer = false;
    std::uint16_t target = 0;
    std::uint8_t count = 0;
    std::uint32_t crc = 0;
    friend constexpr bool operator==(const FlashChecksum&, const FlashChecksum&) = default;
};

// A frame in ORC space that no documented form fits (unknown group or sub-code, wrong length, priority 00,
// a standard frame): shown with its id fields and why, never acted on. `why` is static text.
struct Unknown {
    static constexpr std::string_view name = "orc.unknown";
    std::uint32_t id = 0;
    bool extended = true;
    Bytes payload;
    std::string_view why;
    friend constexpr bool operator==(const Unknown&, const Unknown&) = default;
};

using Message =
    std::variant<AllOff, AllOn, Overload, LocoStop, LocoSpeedQuery, LocoSpeed, LocoSpeedQueryByUid,
                 LocoSpeedByUid, LocoFunctionsQuery, LocoFunctions, LocoFunctionQuery, LocoFunction,
                 AllDecoders, DecoderSwitch, AllEncoders, EncoderQuery, EncoderStatus, Ping, PingAnswer, Find,
                 FindAnswer, AssignBusId, FlashCancel, FlashInit, FlashAccepted, FlashSize, FlashSizeAnswer,
                 FlashData, FlashChecksum, Unknown>;

// The message's name, e.g. "orc.decoder.switch".
std::string_view nameOf(const Message& message);

// Every message name, in declaration order (orc.unknown last).
std::vector<std::string_view> messageNames();

// Whether the message is one of Stellwerk's extensions (FindAnswer, AssignBusId), not in the document.
bool isExtension(const Message& message);

} // namespace stellwerk::orc
