#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace stellwerk::cs2config {

// What a magnetartikel.cs2 `.typ` means for the layout: how many consecutive keyboard addresses the
// article occupies and which `.stellung` values it takes. Turnouts, signals and the rest differ, and
// route steps, address checks and the UI all need to know by how much.
struct AccessoryTypeInfo {
    std::string_view key;         // the file's `.typ` value, e.g. "dreiwegweiche"
    std::string_view description; // English, for people
    int addresses = 1;            // consecutive keyboard addresses, starting at `.id`
    int positions = 2;            // aspects or positions the article has
    std::uint32_t validPositions; // bit n set: `.stellung=n` is a position of this type
    bool singleOutput = false;    // one output of an address; `.ungerade=1` picks the second one
    bool confirmed = true;        // false: counts inferred, not seen in a real file (see AccessoryType.cpp)

    bool acceptsPosition(std::int64_t position) const {
        return position >= 0 && position < 32 && (validPositions >> position & 1U) != 0;
    }
};

// Every type the protocol document (8.2.2) lists, in its order.
std::span<const AccessoryTypeInfo> accessoryTypes();
// The type with this `.typ` value, or null when the document does not know it.
const AccessoryTypeInfo* findAccessoryType(std::string_view key);

} // namespace stellwerk::cs2config
