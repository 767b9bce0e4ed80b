#pragma once

#include "base/Expected.h"
#include "ro/Messages.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace stellwerk::ro {

// The data bytes of one RO frame (at most eight), as the codec writes them.
struct Payload {
    std::array<std::uint8_t, 8> bytes{};
    std::uint8_t size = 0;

    std::span<const std::uint8_t> span() const { return {bytes.data(), size}; }
    friend bool operator==(const Payload& a, const Payload& b) {
        return a.size == b.size && std::equal(a.bytes.begin(), a.bytes.begin() + a.size, b.bytes.begin());
    }
};

// Why a payload is no RO message: what is wrong and which byte (1-based, as 004 counts them; 0 for the
// payload as a whole).
struct DecodeError {
    std::string reason;
    unsigned byte = 0;
};

// How long a read request is: 8 bytes as §1 says every Sendepaket is (the default), or 4, since §3.2.5
// says a read carries no DATA (notes R5). A module profile chooses.
enum class ReadRequestSize : std::uint8_t { Four = 4, Eight = 8 };

// Request -> payload: COMMAND, address (LE), job id, data (LE, zero for a read and beyond the width).
Payload encode(const Request& request, ReadRequestSize readSize = ReadRequestSize::Eight);
// Payload -> request. Refused: an unknown COMMAND, fewer than 4 bytes, a write too short for its width,
// more than 8 bytes, or a written value too wide for the width. A read's padding is ignored.
Expected<Request, DecodeError> decodeRequest(std::span<const std::uint8_t> payload);

// Answer -> payload: OK as 7 bytes (§3.5), 0xFD as 2 bytes plus any data, 0xFE as 1 byte.
Payload encode(const Answer& answer);
// Payload -> answer. Refused: an empty payload, a first byte that is no answer code, an OK shorter than 3
// bytes or with a width code above 4 or a value too wide for it, a 0xFD without job id or with more than
// four data bytes.
Expected<Answer, DecodeError> decodeAnswer(std::span<const std::uint8_t> payload);

} // namespace stellwerk::ro
