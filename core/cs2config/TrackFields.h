#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Node.h"
#include "cs2config/ReportOnce.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

// Reading and writing the `.key=value` lines of one record of a track plan file.
namespace stellwerk::cs2config {

// The record's own `.key` line: an entry one level below it. Deeper lines that a damaged file has
// directly under the record (reported by the parser as "nested without its block") do not count.
const Node* findField(const Node& record, std::string_view key);
Node* findField(Node& record, std::string_view key);

// Reads the typed values of one record. A value it cannot use is reported (when given diagnostics)
// and replaced by the default; the line itself stays as it was.
class TrackFieldReader {
public:
    TrackFieldReader(const Node& record, std::string_view what, Diagnostics* diagnostics)
        : record_(record), what_(what), diagnostics_(diagnostics) {}

    bool has(std::string_view key) const { return findField(record_, key) != nullptr; }
    // The line of the key, or of the record when the key is missing.
    int line(std::string_view key) const;
    std::int64_t integer(std::string_view key, std::int64_t absent, std::int64_t min, std::int64_t max) const;
    // nullopt when the key is missing or its value unusable; `fallback` says what is done instead.
    std::optional<std::int64_t> optionalInteger(std::string_view key, std::int64_t min, std::int64_t max,
                                                std::string_view fallback = "ignored") const;
    // The value exactly as written (empty when missing).
    std::string text(std::string_view key) const;
    // The value without surrounding blanks, for keywords such as `.typ`.
    std::string word(std::string_view key) const;

    void warn(std::string_view key, std::string message, std::string action) const;

private:
    const Node& record_;
    std::string_view what_;
    Diagnostics* diagnostics_;
};

// Writes `.key=value` lines of one record, finding them the way TrackFieldReader does. A changed
// value rewrites its line only; a missing key is added at the end of the record (or first, for
// setIntegerFirst), where it cannot take any other line under it. Numbers keep their written form ("0x05")
// while they still mean the same number.
class TrackFieldWriter {
public:
    enum class Base { Decimal, Hex };

    TrackFieldWriter(Node& record, const LineStyle& style) : record_(record), style_(style) {}

    // A value is one line: a line feed in it, or a carriage return at its end, is written as a space.
    void setText(std::string_view key, std::string_view value);
    // Like setText, but a missing key is only added when the value is not empty.
    void setOptionalText(std::string_view key, std::string_view value);
    // A missing key is only added when the value differs from `absentMeans`.
    void setInteger(std::string_view key, std::int64_t value, Base base = Base::Decimal,
                    std::optional<std::int64_t> absentMeans = std::nullopt);
    // Like setInteger, but a missing key is added as the record's first line, where a CS2 writes `.id`.
    void setIntegerFirst(std::string_view key, std::int64_t value, Base base, std::int64_t absentMeans);
    void remove(std::string_view key);

private:
    void add(std::string_view key, std::string_view value, bool first);
    bool canPutFirst() const;

    Node& record_;
    const LineStyle& style_;
};

// Reports keys of a record that are not in `known` (once per key and file), and known keys given
// twice in one record.
void checkRecordKeys(const Node& record, std::span<const std::string_view> known, std::string_view what,
                     ReportOnce& unknownKeys, Diagnostics& diagnostics);

} // namespace stellwerk::cs2config
