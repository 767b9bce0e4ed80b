#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

namespace stellwerk::orc {

// The identities of OpenRailCAN devices (001 §Bus ID Vergabe): a CAN device has a 32-bit UID, Word1 a
// developer code and Word2 the developer's running number; its bus id is the UID's low 16 bits unless the
// central has to count up. A legacy device (MM, DCC, ...) has no UID: UID = bus id = range base + number.

// Word1 from a developer's name: (surname[0] XOR firstName[1]) << 8 | (surname[1] XOR firstName[0]), case as
// written ("Michael", "Schwarzer" -> 0x3A2E). Empty when a name has fewer than two letters.
std::optional<std::uint16_t> developerWord(std::string_view firstName, std::string_view surname);

constexpr std::uint32_t makeUid(std::uint16_t word1, std::uint16_t word2) {
    return std::uint32_t(word1) << 16 | word2;
}
// The bus id a CAN device asks for: the UID's low 16 bits.
constexpr std::uint16_t wantedBusId(std::uint32_t uid) {
    return std::uint16_t(uid & 0xFFFF);
}

// The first free bus id from the wanted one upwards ("zählt die Zentrale einfach 'hoch'"), wrapping at
// 0xFFFF; empty when every id is taken.
std::optional<std::uint16_t> firstFreeBusId(std::uint16_t wanted,
                                            const std::function<bool(std::uint16_t)>& taken);

// The ranges of legacy devices. The document keeps MM locos and MM2 decoders; the others were lost in its
// table and are filled from the CS2 Loc-ID schema (notes A3.1): marked `assumed`.
enum class LegacyKind : std::uint8_t { MmLoco, Sx1Loco, Mm2Decoder, DccAccessory, MfxLoco, DccLoco };

struct LegacyRange {
    LegacyKind kind;
    std::string_view name;
    std::uint16_t base;
    std::uint16_t last;
    bool assumed;
};

const LegacyRange& legacyRange(LegacyKind kind);

// Ziel-Id of legacy device `number` (base + number, as the document's "MM2 Weiche 5 = 0x3005"); empty when
// the number is 0 or beyond the range.
std::optional<std::uint16_t> legacyId(LegacyKind kind, unsigned number);

// The range a bus id falls in, if any, and the user number in it.
struct LegacyAddress {
    const LegacyRange* range = nullptr;
    unsigned number = 0;
};
std::optional<LegacyAddress> legacyAddressOf(std::uint16_t busId);

} // namespace stellwerk::orc
