#pragma once

#include <cstdint>

namespace stellwerk::mcan {

// The three ways an M-CAN identifier is read (notes B§1.2). Every one is the same partition of the 29 bits:
// priority (28..26), a 16-bit field (25..10), three bits (9..7) and the sender's node (6..0); only the
// meaning of the middle fields changes with the node number.
//   session: prio | object handle (16)                  | cmd  | node
//   login:   111  | UID byte (8) | stage (3) | MID (5)  | 00 dir | 126
//   flash:   111  | handle (8)   | request (3) | stage (5) | flags | 127
enum class Layout : std::uint8_t { Session, Login, Flash };

inline constexpr std::uint8_t LoginNode = 126;
inline constexpr std::uint8_t FlashNode = 127;
inline constexpr std::uint8_t TopPrio = 0b111;
// The one frame with priority 000 and cmd 111 from node 0 ("CAN-Bus belegt", document 6.1).
inline constexpr std::uint32_t BusBusyId = 0x380;

// Priorities of the session layout (document 6.3.1), lowest priority (highest value) first.
namespace prio {
inline constexpr std::uint8_t Login = 0b111;
inline constexpr std::uint8_t Data = 0b110;       // handles, names, lists, descriptions
inline constexpr std::uint8_t Throttle = 0b101;   // take / release a locomotive
inline constexpr std::uint8_t Status = 0b100;     // stop / go; status values
inline constexpr std::uint8_t Master = 0b011;     // master drives a locomotive; cyclic monitoring
inline constexpr std::uint8_t SlaveDrive = 0b010; // slave drives a locomotive
} // namespace prio

// The cmd field of the session layout (document 6.3.1; 110 is never used: the CS2 marks its hashes with it).
namespace cmd {
inline constexpr std::uint8_t State = 0b000;     // loco assignment, take / release
inline constexpr std::uint8_t Name = 0b001;      // names, stack size, loco type, rail format
inline constexpr std::uint8_t List = 0b010;      // status list and values, functions
inline constexpr std::uint8_t Object = 0b011;    // SY handle, loco-stack lists
inline constexpr std::uint8_t Handle = 0b100;    // SD handle; master adds a loco
inline constexpr std::uint8_t Delete = 0b101;    // master deletes a loco
inline constexpr std::uint8_t Cs2Marker = 0b110; // never M-CAN
inline constexpr std::uint8_t Monitor = 0b111;   // cyclic monitoring (and the bus-busy frame)
} // namespace cmd

struct SessionId {
    std::uint8_t prio = 0;
    std::uint16_t handle = 0;
    std::uint8_t cmd = 0;
    std::uint8_t node = 0;
};

struct LoginId {
    std::uint8_t uidByte = 0;
    std::uint8_t stage = 0; // 0..7
    std::uint8_t mid = 0;   // 0..31
    bool fromMaster = false;
};

struct FlashId {
    std::uint8_t handle = 0;
    std::uint8_t request = 0; // 3 bits
    std::uint8_t stage = 0;   // 5 bits
    std::uint8_t flags = 0;   // 3 bits
};

constexpr std::uint32_t sessionId(const SessionId& s) {
    return (std::uint32_t(s.prio & 7) << 26) | (std::uint32_t(s.handle) << 10) |
           (std::uint32_t(s.cmd & 7) << 7) | (s.node & 0x7F);
}
constexpr SessionId readSession(std::uint32_t id) {
    return {std::uint8_t((id >> 26) & 7), std::uint16_t((id >> 10) & 0xFFFF), std::uint8_t((id >> 7) & 7),
            std::uint8_t(id & 0x7F)};
}

constexpr std::uint32_t loginId(const LoginId& l) {
    return (std::uint32_t(TopPrio) << 26) | (std::uint32_t(l.uidByte) << 18) |
           (std::uint32_t(l.stage & 7) << 15) | (std::uint32_t(l.mid & 0x1F) << 10) |
           (std::uint32_t(l.fromMaster ? 1 : 0) << 7) | LoginNode;
}
constexpr LoginId readLogin(std::uint32_t id) {
    return {std::uint8_t((id >> 18) & 0xFF), std::uint8_t((id >> 15) & 7), std::uint8_t((id >> 10) & 0x1F),
            ((id >> 7) & 1) != 0};
}

constexpr std::uint32_t flashId(const FlashId& f) {
    return (std::uint32_t(TopPrio) << 26) | (std::uint32_t(f.handle) << 18) |
           (std::uint32_t(f.request & 7) << 15) | (std::uint32_t(f.stage & 0x1F) << 10) |
           (std::uint32_t(f.flags & 7) << 7) | FlashNode;
}
constexpr FlashId readFlash(std::uint32_t id) {
    return {std::uint8_t((id >> 18) & 0xFF), std::uint8_t((id >> 15) & 7), std::uint8_t((id >> 10) & 0x1F),
            std::uint8_t((id >> 7) & 7)};
}

// Which layout an M-CAN identifier has: nodes 126 and 127 with the top priority are login and flash.
constexpr Layout layoutOf(std::uint32_t id) {
    const std::uint8_t node = std::uint8_t(id & 0x7F);
    if (((id >> 26) & 7) == TopPrio && node == LoginNode)
        return Layout::Login;
    if (((id >> 26) & 7) == TopPrio && node == FlashNode)
        return Layout::Flash;
    return Layout::Session;
}

// Odd nodes are slaves (MS1), even nodes masters (document 5.4.1); 126 and 127 say nothing by themselves.
constexpr bool isSlaveNode(std::uint8_t node) {
    return (node & 1) != 0 && node < LoginNode;
}

// The CS2 marks its hashes with 110 in bits 9..7 (CS2 document 1.2.4), a value M-CAN never uses as cmd.
constexpr bool hasCs2Marker(std::uint32_t id) {
    return (id & 0x380) == 0x300;
}

// Whether a 29-bit identifier is an M-CAN frame on a bus shared with the CS2 protocol (notes B§6.2): the CS2
// marker first; then the bus-busy frame; then any frame with priority bits 28..26 set (CS2 frames use
// priority 0 and commands up to 0x3x, so those bits are clear). An unmarked frame with priority 0 is the
// CS2's (an MS2's plain hash, a Gleisbox's swapped one).
constexpr bool isMcanId(std::uint32_t id) {
    if (hasCs2Marker(id))
        return false;
    return id == BusBusyId || ((id >> 26) & 7) != 0;
}

} // namespace stellwerk::mcan
