#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace stellwerk::cs2 {

// The classes of input the decoder refuses; each carries enough context to say what was wrong.
enum class DecodeErrorKind : std::uint8_t {
    DlcOutOfRange,    // DLC above 8: a broken sender
    IdOutOfRange,     // identifier bits above bit 28 set (13-byte form), or a standard 11-bit identifier
    TooShort,         // fewer data bytes than the command's shortest form
    UnexpectedLength, // a DLC that none of the command's forms has
    ReservedValue,    // a value the document reserves or excludes
};

std::string_view decodeErrorKindName(DecodeErrorKind kind);

// Why a frame could not be decoded. `detail` is static text naming the field and the rule.
struct DecodeError {
    DecodeErrorKind kind;
    std::uint8_t command = 0;
    std::uint8_t dlc = 0;
    std::string_view detail;

    // A sentence a person can act on, e.g. "loco.speed: unexpected length 5 (needs 4 or 6 data bytes)".
    std::string message() const;
};

} // namespace stellwerk::cs2
