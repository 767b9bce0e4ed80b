#pragma once

#include <cstdint>
#include <string_view>
#include <variant>

namespace stellwerk::ro {

// How many bits one register access covers (004 §3.2.1/§3.2.2): the low nibble of COMMAND, and the
// "Prüfung" code of an OK answer (§3.5.1), where None means "Keine Daten" (the answer to a write).
enum class Width : std::uint8_t { None = 0, Bit = 1, Byte = 2, Word = 3, Long = 4 };

// "bit", "byte", "word", "long" ("none" for None); and back (nullopt-like: false for an unknown word).
std::string_view widthName(Width width);
bool widthFromName(std::string_view name, Width& width);
// Data bytes an access of this width carries (004 §3.5.2.1 table: bit and byte 1, word 2, long 4).
unsigned byteCount(Width width);
// The largest value an access of this width can carry (bit: 1).
std::uint32_t maxValue(Width width);

// A request ("Sendepaket", 004 §3.2) from the master to a module: write (COMMAND 0x1w) or read (0x2w) at a
// 16-bit byte address, marked by a job id. `value` is the data of a write and is 0 for a read.
struct Request {
    enum class Kind : std::uint8_t { Write = 0x10, Read = 0x20 };
    Kind kind = Kind::Write;
    Width width = Width::Byte; // Bit .. Long; never None
    std::uint16_t address = 0;
    std::uint8_t job = 0;
    std::uint32_t value = 0;

    bool isWrite() const { return kind == Kind::Write; }
    // COMMAND, the first byte: 0x11..0x14 or 0x21..0x24.
    std::uint8_t command() const { return std::uint8_t(std::uint8_t(kind) | std::uint8_t(width)); }
    // "ro.write-word", "ro.read-bit", ...
    std::string_view name() const;
    friend bool operator==(const Request&, const Request&) = default;
};

// "OK"-Antwortpaket (004 §3.5.1): the request with this job id was done; a read's data in `value`.
struct OkAnswer {
    static constexpr std::string_view name = "ro.ok";
    Width width = Width::None;
    std::uint8_t job = 0;
    std::uint32_t value = 0;
    friend bool operator==(const OkAnswer&, const OkAnswer&) = default;
};

// Fehlercode 0xFD "JOB-ID doppelt" (004 §3.5.2.1): the module already had a request with this job id.
// The table below it hints that a read's data may follow the job id (notes R10): `dataBytes` of them.
struct DuplicateJobAnswer {
    static constexpr std::string_view name = "ro.duplicate-job";
    std::uint8_t job = 0;
    std::uint8_t dataBytes = 0; // 0..4
    std::uint32_t value = 0;
    friend bool operator==(const DuplicateJobAnswer&, const DuplicateJobAnswer&) = default;
};

// Fehlercode 0xFE "ungültiger Befehl" (004 §3.5.2.2): the last request had an invalid command. It carries
// no job id, so it belongs to the one request in flight.
struct InvalidCommandAnswer {
    static constexpr std::string_view name = "ro.invalid-command";
    friend bool operator==(const InvalidCommandAnswer&, const InvalidCommandAnswer&) = default;
};

// An answer ("Antwortpaket", 004 §3.5) from a module.
using Answer = std::variant<OkAnswer, DuplicateJobAnswer, InvalidCommandAnswer>;

std::string_view nameOf(const Answer& answer);

// First bytes that tell an answer apart (004 §3.5): disjoint from the request commands.
namespace answer_code {
inline constexpr std::uint8_t Ok = 0x01;
inline constexpr std::uint8_t DuplicateJob = 0xFD;
inline constexpr std::uint8_t InvalidCommand = 0xFE;
} // namespace answer_code

} // namespace stellwerk::ro
