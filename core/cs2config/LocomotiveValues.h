#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Locomotive.h"
#include "cs2config/Node.h"
#include "cs2config/ReportOnce.h"
#include "cs2config/Values.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

// Reading helpers shared by the locomotive file, the loco status file and the MS2 loco streams.
// The writers use the same functions to decide whether a line still holds a value.
namespace stellwerk::cs2config::loco {

enum class ValueProblem : std::uint8_t { None, Missing, NotANumber, OutOfRange };

// A value read from a line, and why the fallback was used instead, if it was.
template <class T>
struct ReadValue {
    T value;
    ValueProblem problem = ValueProblem::None;
};

// The number a line holds; the fallback when the line is missing, holds no number or one that T
// cannot hold.
template <class T>
ReadValue<T> readNumber(const Node* line, T fallback) {
    if (!line || !line->hasValue())
        return {fallback, ValueProblem::Missing};
    const std::optional<std::int64_t> number = parseInteger(line->value());
    if (!number)
        return {fallback, ValueProblem::NotANumber};
    if (!std::in_range<T>(*number))
        return {fallback, ValueProblem::OutOfRange};
    return {static_cast<T>(*number), ValueProblem::None};
}

// How text values are written: as is (CS2) or with "#20"-style escapes (CS3-native files).
enum class TextCoding : std::uint8_t { Plain, Cs3Escaped };

std::string cs3Unescape(std::string_view text);
std::string cs3Escape(std::string_view text);
// The text of a line's value (empty when missing), unescaped for CS3-native files.
std::string readText(const Node* line, TextCoding coding);
ReadValue<TravelDirection> readDirection(const Node* line);
// ".key" / "..key" as the key is written at its level, for messages.
std::string keyLabel(const Node& line);
std::string keyLabel(int level, std::string_view key);
// "'BR 85' (line 7)" or "line 7" for a locomotive without a name, for messages about two records.
std::string describe(std::string_view name, int line);
// "'BR 85'" or "at line 7" for a locomotive without a name, for messages about the record at hand.
std::string nameOf(std::string_view name, int line);

// Problems that repeat from record to record (an unknown key, an unusual value). Each is reported
// once, at the first line where it occurs, with how often it occurred.
class Findings {
public:
    enum class Kind : std::uint8_t { UnknownKey, MissingKey, Other };

    void note(Kind kind, std::string subject, std::string message, std::string action, int line);
    // Reports every finding; with `skipKeys`, unknown and missing keys are left to the caller.
    void report(Diagnostics& diagnostics, bool skipKeys = false) const;
    // The subjects (".blocks") of the findings of one kind, in the order they were first seen.
    std::vector<std::string> subjects(Kind kind) const;

private:
    struct Finding {
        Kind kind;
        std::string subject;
        std::string message;
        std::string action;
        int line;
        std::size_t count;
    };

    std::vector<Finding> findings_;
    ReportOnce messages_; // numbered like findings_
};

// The lines of one record (or block) for a fixed list of keys, found in one pass over its children.
// Block keys are skipped (the caller walks them in order); any other key is noted as unknown, and
// a key that appears twice is reported (the first one is used).
class RecordLines {
public:
    static constexpr std::size_t maxKeys = 32;

    struct Keys {
        std::span<const std::string_view> values;
        std::span<const std::string_view> blocks;
        std::string_view recordName; // "locomotive record", for messages
    };

    RecordLines(const Node& record, const Keys& keys, Diagnostics& diagnostics, Findings& findings);

    const Node* operator[](std::size_t index) const { return lines_[index]; }
    // The first of two keys that is present (".xprot" or the older ".xprotokoll").
    const Node* either(std::size_t first, std::size_t second) const {
        return lines_[first] ? lines_[first] : lines_[second];
    }

private:
    std::array<const Node*, maxKeys> lines_{};
};

// Reads numbers and text out of lines and reports, at the line, a value it cannot read.
class ValueReader {
public:
    ValueReader(Diagnostics& diagnostics, TextCoding coding) : diagnostics_(diagnostics), coding_(coding) {}

    template <class T>
    T number(const Node* line, T fallback) {
        const ReadValue<T> read = readNumber(line, fallback);
        if (read.problem == ValueProblem::NotANumber || read.problem == ValueProblem::OutOfRange)
            reportNumber(*line, read.problem, static_cast<std::int64_t>(fallback));
        return read.value;
    }
    std::string text(const Node* line) const { return readText(line, coding_); }
    TextCoding coding() const { return coding_; }

private:
    void reportNumber(const Node& line, ValueProblem problem, std::int64_t fallback);

    Diagnostics& diagnostics_;
    TextCoding coding_;
};

} // namespace stellwerk::cs2config::loco
