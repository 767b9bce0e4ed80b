#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace stellwerk::busreading {

// An MS1 handheld as the frames of a bus name it (M-CAN): the slave node of its node pair (its master
// speaks from the node below) and the name it sent, empty until the bus has carried it. The monitor's
// handheld filter compares rows by it.
struct Handheld {
    std::uint8_t node = 0;
    std::string name;
};

// A handheld as people type it into a filter: either node of its pair ("43", or its master's "42"), or the
// name it sent ("KS MS1", in any case).
class HandheldReference {
public:
    // nullopt for an empty text and for a number that is no node of a pair (above 125).
    static std::optional<HandheldReference> parse(std::string_view text);

    bool matches(const Handheld& handheld) const;
    bool operator==(const HandheldReference&) const = default;

private:
    std::optional<std::uint8_t> node_; // the slave node of the pair
    std::string name_;                 // lower case, without surrounding blanks
};

} // namespace stellwerk::busreading
