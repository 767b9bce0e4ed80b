#pragma once

#include "base/Expected.h"
#include "cs2/LocId.h"
#include "cs2/Messages.h"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace stellwerk::cs2 {

// How a field's number is shown: quantities in decimal, identifiers in hex, flags as booleans.
enum class FieldFormat : std::uint8_t { Decimal, Hex, Bool, Text };

// A symbolic name for one value of a byte (direction "forward" = 1, ...).
struct NamedValue {
    std::uint8_t value;
    std::string_view name;
};

// The single place that lists a message's fields. Each message's bind() walks its fields through
// a binder; the Describer reads them out for people and scripts, the Assigner fills them from
// key=value text. Keeping both on one list means the CLI can encode whatever it can decode.
class FieldBinder {
public:
    virtual ~FieldBinder() = default;

    // Whether the frame is a response; some layouts mean different things in each direction.
    virtual bool response() const = 0;
    // The frame's hash field (a packet number in stream frames).
    virtual std::uint16_t hash() const = 0;

    // `limit` narrows the type's range (0 = the whole type), e.g. to the 10 bits of a CV number.
    template <class T>
    void number(std::string_view key, T& value, FieldFormat format = FieldFormat::Decimal, unsigned scale = 1,
                std::uint64_t limit = 0) {
        NumberSlot slot{key, format, scale, false, true, std::uint64_t(value), limit ? limit : maxOf<T>()};
        if (onNumber(slot))
            value = T(slot.value);
    }
    template <class T>
    void number(std::string_view key, std::optional<T>& value, FieldFormat format = FieldFormat::Decimal,
                unsigned scale = 1) {
        NumberSlot slot{key,       format, scale, true, value.has_value(), std::uint64_t(value.value_or(0)),
                        maxOf<T>()};
        if (onNumber(slot))
            value = slot.present ? std::optional<T>(T(slot.value)) : std::nullopt;
    }
    // A byte (or bit field of one) shown by name; other values are shown as numbers.
    void named(std::string_view key, std::uint8_t& byte, std::span<const NamedValue> names,
               std::uint8_t mask = 0xFF);
    void named(std::string_view key, std::optional<std::uint8_t>& byte, std::span<const NamedValue> names);
    template <class E>
    void enumerated(std::string_view key, E& value, std::span<const NamedValue> names) {
        auto raw = std::uint8_t(value);
        named(key, raw, names);
        value = E(raw);
    }
    // One bit of a byte as a boolean.
    void flag(std::string_view key, std::uint8_t& byte, std::uint8_t bit);
    void boolean(std::string_view key, std::optional<bool>& value);

    virtual void loco(std::string_view key, LocId& id) = 0;
    virtual void loco(std::string_view key, std::optional<LocId>& id) = 0;
    virtual void chars(std::string_view key, std::array<char, 8>& text) = 0;
    virtual void bytes(std::string_view key, RawBytes& raw) = 0;
    virtual void bytes(std::string_view key, std::array<std::uint8_t, 8>& data) = 0;
    // Derived text shown to people (a device type's name); ignored when building.
    virtual void note(std::string_view key, std::string_view text) = 0;
    // A software version (major << 8 | minor) shown as "major.minor".
    virtual void version(std::string_view key, std::optional<std::uint16_t>& version) = 0;
    // A value fixed by the message type or frame (sub-command, packet number); ignored when building.
    virtual void fixed(std::string_view key, std::uint64_t value, FieldFormat format) = 0;

protected:
    struct NumberSlot {
        std::string_view key;
        FieldFormat format;
        unsigned scale; // shown value = stored value * scale
        bool optional;
        bool present;
        std::uint64_t value;
        std::uint64_t max;
        std::span<const NamedValue> names = {};
        std::uint8_t mask = 0xFF; // for bit fields of one byte
    };
    // Returns true when the binder changed slot.value/slot.present.
    virtual bool onNumber(NumberSlot& slot) = 0;

private:
    template <class T>
    static constexpr std::uint64_t maxOf() {
        if constexpr (std::is_same_v<T, bool>)
            return 1;
        else
            return std::uint64_t(std::numeric_limits<T>::max());
    }
};

// One described field, ready to print.
struct Field {
    std::string_view key;
    FieldFormat format = FieldFormat::Decimal;
    std::uint64_t number = 0;
    std::string text;     // for FieldFormat::Text
    unsigned digits = 0;  // hex width
    bool derived = false; // shown for information (sub-command, names); not accepted when building
};

// All fields of a message in their natural order.
std::vector<Field> describe(const Message& message);

// A key=value argument of the CLI encoder.
using KeyValue = std::pair<std::string, std::string>;

// Builds a message from its vocabulary name and key=value arguments (prio, response and hash
// included); the error names the key and the rule it broke.
Expected<Message, std::string> buildMessage(std::string_view name, std::span<const KeyValue> arguments);

// Every message name of the vocabulary, in declaration order (unknown first).
std::vector<std::string_view> messageNames();

} // namespace stellwerk::cs2
