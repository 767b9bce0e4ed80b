#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/JsonWriter.h"
#include "cs2config/Node.h"
#include "cs2config/RecordEditor.h"
#include "cs2config/ReportOnce.h"

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// Shared by the accessory, accessory status and route models: reading typed values out of a record with
// honest diagnostics, and writing them back so that a value whose meaning did not change keeps its line.
namespace stellwerk::cs2config::accessories {

// The value a reader takes from a record; the writer compares against the same reading of the source, so
// that "0x05", " 5" or an unreadable "abc" stay as they are while the model still holds what was read.
std::optional<std::int64_t> integerIn(const Node& record, std::string_view key);
std::int64_t integerIn(const Node& record, std::string_view key, std::int64_t absentMeans);
std::string textIn(const Node& record, std::string_view key);
// A word the format defines (`.typ`, `.dectyp`): trimmed, since streams may pad their lines with spaces.
std::string keywordIn(const Node& record, std::string_view key);

// A JSON number, or null when the file had no such value.
void writeOptional(JsonWriter& json, std::string_view key, const std::optional<std::int64_t>& value);

// Says each unknown key, record kind or value once per file, with the line of its first occurrence:
// 127 records with the same unknown key make one report, not 127.
class OnceReporter {
public:
    explicit OnceReporter(Diagnostics& diagnostics) : diagnostics_(diagnostics) {}

    Diagnostics& diagnostics() { return diagnostics_; }
    // Reports children of `record` whose key is not in `known` ("unknown key .foo in artikel records", once
    // per file) and keys given twice in one record unless they are `repeatable` blocks (each time).
    void checkKeys(const Node& record, std::string_view where, std::initializer_list<std::string_view> known,
                   std::initializer_list<std::string_view> repeatable = {});
    void unknownRecord(const Node& record);
    // A ".key" line before any record.
    void strayLine(const Node& line);
    // Reports `message` unless a report with the same `topic` was made before.
    void once(std::string_view topic, int line, std::string message, std::string action);

private:
    Diagnostics& diagnostics_;
    ReportOnce seen_;
};

// Reads one record's typed values and reports what does not fit: values that are not numbers (the
// text is kept, a default is used) and missing required keys.
class RecordReader {
public:
    RecordReader(const Node& record, std::string_view name, Diagnostics& diagnostics)
        : record_(record), name_(name), diagnostics_(diagnostics) {}

    std::int64_t integer(std::string_view key, std::int64_t absentMeans);
    std::optional<std::int64_t> optionalInteger(std::string_view key);
    // Like integer(), but a missing key is reported as an error.
    std::int64_t required(std::string_view key);
    std::string text(std::string_view key) const { return textIn(record_, key); }
    std::string keyword(std::string_view key) const { return keywordIn(record_, key); }
    bool has(std::string_view key) const { return record_.find(key) != nullptr; }

private:
    bool readable(std::string_view key, const char* fallback);
    std::string dottedKey(std::string_view key) const;

    const Node& record_;
    std::string_view name_;
    Diagnostics& diagnostics_;
};

// Writes typed values into a copy of a record's source lines: a line changes only when the value the
// reader would take from it differs from the model's.
class RecordWriter {
public:
    RecordWriter(Node& record, const Node& source, const LineStyle& style)
        : editor_(record, style), source_(source) {}

    void integer(std::string_view key, std::int64_t value, std::int64_t absentMeans,
                 RecordEditor::Base base = RecordEditor::Base::Decimal);
    // A key the reader requires: a new record always gets it.
    void required(std::string_view key, std::int64_t value);
    // 0/1 with a missing key meaning `absentMeans`; any other number the file holds counts as 1.
    void flag(std::string_view key, bool value, bool absentMeans = false);
    // nullopt removes the key.
    void optionalInteger(std::string_view key, std::optional<std::int64_t> value);
    // A missing key is only added when the value is not empty.
    void optionalText(std::string_view key, std::string_view value);
    // Like optionalText, but a line whose trimmed text is the value stays as it is.
    void optionalKeyword(std::string_view key, std::string_view value);
    RecordEditor& editor() { return editor_; }

private:
    RecordEditor editor_;
    const Node& source_;
};

// The record's own source, or a new record line when it has none (an item added to the model).
Node recordFrom(const Node& source, const Document& document, std::string_view keyword);
// A sub-block's own source, or a new "<indent>.<key>" line.
Node blockFrom(const Node& source, std::string_view key, const LineStyle& style);

// Puts `blocks` where the record's `key` blocks stood: the n-th block takes the n-th old place, extra ones
// follow the last old one (or go before the first `before` block, or at the end), surplus places go.
// Unchanged blocks in unchanged order give back the same lines.
void placeBlocks(Node& record, std::string_view key, std::vector<Node> blocks, std::string_view before = {});
// Every line of the record but the last ends with a line end; the last one gets `lastEnding` (a record at
// the end of a file without a final newline keeps having none).
void endLines(Node& record, Node::Ending lastEnding, const LineStyle& style);

// The file's "version" record (.major/.minor); a second one is reported.
struct FileVersion {
    std::optional<std::int64_t> major;
    std::optional<std::int64_t> minor;
};
FileVersion readVersion(const Document& document, OnceReporter& reporter);
// Updates the version record (adds one when the model has a version and the file had none).
void writeVersion(Document& document, const FileVersion& version);
// "version": {"major", "minor"}, a missing one as null.
void writeVersionJson(JsonWriter& json, const FileVersion& version);

// Warns when the file has a header other than `[expected]`: "section [x] instead of [expected]", "read as
// <readAs>".
void checkSection(const Document& document, std::string_view expected, std::string_view readAs,
                  Diagnostics& diagnostics);

} // namespace stellwerk::cs2config::accessories
