#pragma once

#include <cstdint>

namespace stellwerk::orc {

// Where the OpenRailCAN fields sit in a 29-bit identifier. The document prints 30 bits of fields
// (001 §Grundsätzlicher ID Aufbau); Stellwerk uses layout L2 of the notes (A1.3), aligned with the CS2
// identifier: priority on the CS2 priority bits, the command group on the CS2 command bits (so that every
// ORC group reads as a CS2 command >= 0x80, which no Märklin node acts on), the direction on the CS2
// response bit and the sender's bus id on the CS2 hash. The device type keeps two of its three bits.
// This table is the only place that knows the layout: the literal layout L1 is a change here.
struct IdField {
    unsigned shift = 0;
    unsigned width = 0;
    constexpr std::uint32_t mask() const { return (std::uint32_t(1) << width) - 1; }
    constexpr std::uint32_t put(std::uint32_t value) const { return (value & mask()) << shift; }
    constexpr std::uint32_t get(std::uint32_t id) const { return (id >> shift) & mask(); }
};

struct IdLayout {
    IdField prio;
    IdField type;
    IdField group;
    IdField direction;
    IdField busId;
};

// L2: prio ID28-27 | device type ID26-25 | group ID24-17 | D ID16 | sender bus id ID15-0.
inline constexpr IdLayout Layout{{27, 2}, {25, 2}, {17, 8}, {16, 1}, {0, 16}};

// Command groups (001 §Befehlssatz): they start at 0x80 "als Unterscheidung zu bisher vorhandenen Kommandos".
namespace group {
inline constexpr std::uint8_t System = 0x80;     // every device
inline constexpr std::uint8_t Loco = 0x81;       // boosters and throttles
inline constexpr std::uint8_t Decoder = 0x88;    // stationary outputs
inline constexpr std::uint8_t Encoder = 0x89;    // inputs, feedback
inline constexpr std::uint8_t Management = 0x90; // ping, find (and Stellwerk's bus-id assignment)
inline constexpr std::uint8_t Flash = 0xF0;      // firmware (the headings print 0x90, the tables 0xF0)
} // namespace group

// Priorities (lower wins arbitration; 0b00 is never sent, "zwecks Märklin/ESU Kollisionsvermeidung"). The
// document gives 01..11 no meaning; Stellwerk's choice (notes A1.4).
namespace prio {
inline constexpr std::uint8_t Safety = 0b01;     // all off / on, loco emergency stop, overload
inline constexpr std::uint8_t Control = 0b10;    // control, queries, answers, encoder events
inline constexpr std::uint8_t Management = 0b11; // ping, find, assignment, flash
} // namespace prio

// Device types (3 bits in the document; the wire carries 0..3, types 4..7 are registry attributes only).
enum class DeviceType : std::uint8_t {
    System = 0,        // central, booster, ...
    Loco = 1,          // locomotives (and the throttles that speak for them)
    CanDecoder = 2,    // stationary outputs on CAN
    CanEncoder = 3,    // inputs on CAN
    LegacyDecoder = 4, // e.g. a DCC decoder driven by a track processor
    LegacyEncoder = 5, // e.g. an S88 module
};
inline constexpr std::uint8_t WireTypeCount = 4;

// Everything an identifier says.
struct Header {
    std::uint8_t prio = prio::Control;
    std::uint8_t type = 0; // DeviceType 0..3
    std::uint8_t group = 0;
    bool answer = false; // D: 0 command or query, 1 answer or event
    std::uint16_t busId = 0;
    friend constexpr bool operator==(const Header&, const Header&) = default;
};

constexpr std::uint32_t makeId(const Header& h) {
    return Layout.prio.put(h.prio) | Layout.type.put(h.type) | Layout.group.put(h.group) |
           Layout.direction.put(h.answer ? 1 : 0) | Layout.busId.put(h.busId);
}

constexpr Header readId(std::uint32_t id) {
    return {std::uint8_t(Layout.prio.get(id)), std::uint8_t(Layout.type.get(id)),
            std::uint8_t(Layout.group.get(id)), Layout.direction.get(id) != 0,
            std::uint16_t(Layout.busId.get(id))};
}

// Whether a 29-bit identifier is in ORC space (notes A7, C4): a group >= 0x80 and a priority other than 00.
// Under L2 that is "ID24 set (the top bit of the CS2 command, which Märklin's commands never set) and
// id >> 27 != 0"; ids with ID24 set and priority 00 are left to 29-bit RO modules.
constexpr bool isOrcId(std::uint32_t id) {
    return id <= 0x1FFFFFFF && Layout.group.get(id) >= 0x80 && Layout.prio.get(id) != 0;
}

} // namespace stellwerk::orc
