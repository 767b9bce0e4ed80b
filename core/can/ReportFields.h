#pragma once

#include "can/CanFrame.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::can {

// How a field's number is shown: quantities in decimal, identifiers in hex, flags as booleans.
enum class FieldFormat : std::uint8_t { Decimal, Hex, Bool, Text };

// One field of a decoded message as people and scripts read it (the M-CAN and OpenRailCAN frame reports).
struct Field {
    std::string_view key;
    std::uint64_t number = 0;
    FieldFormat format = FieldFormat::Decimal;
    std::string text;    // Text fields only
    unsigned digits = 2; // Hex fields: at least this many digits
};

// Collects a message's fields in the order they are shown.
struct FieldList {
    FieldList& number(std::string_view key, std::uint64_t value);
    FieldList& hex(std::string_view key, std::uint64_t value, unsigned digits = 2);
    FieldList& flag(std::string_view key, bool value);
    FieldList& text(std::string_view key, std::string_view value);
    std::vector<Field> list;
};

// `value` in upper-case hex with at least `digits` digits, without "0x".
std::string hexDigits(std::uint64_t value, unsigned digits);
// "key=value key=value": hex as 0x.., flags as true/false, texts quoted where they hold a space.
std::string fieldsText(const std::vector<Field>& fields);
// The report of a frame as one line: the frame in document notation, two spaces, the message name, two
// spaces, its fields as fieldsText writes them.
std::string reportText(const CanFrame& frame, std::string_view name, const std::vector<Field>& fields);
// The report of a frame as one JSON object: id, dlc, data (candump notation), message name and fields.
std::string reportJson(const CanFrame& frame, std::string_view name, const std::vector<Field>& fields);
// The number of the field `key` (not a text field), or nullopt.
std::optional<std::uint64_t> fieldNumber(const std::vector<Field>& fields, std::string_view key);

} // namespace stellwerk::can
