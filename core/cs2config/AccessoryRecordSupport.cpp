#include "cs2config/AccessoryRecordSupport.h"

#include "cs2config/Text.h"
#include "cs2config/Values.h"

#include <algorithm>
#include <map>

namespace stellwerk::cs2config::accessories {

namespace {

std::string dotted(const Node& line) {
    return std::string(static_cast<std::size_t>(std::max(line.level(), 0)), '.') + std::string(line.key());
}

void collectLines(Node& node, std::vector<Node*>& lines) {
    lines.push_back(&node);
    for (Node& child : node.children())
        collectLines(child, lines);
}

} // namespace

std::optional<std::int64_t> integerIn(const Node& record, std::string_view key) {
    const std::optional<std::string_view> value = record.valueOf(key);
    return value ? parseInteger(*value) : std::nullopt;
}

std::int64_t integerIn(const Node& record, std::string_view key, std::int64_t absentMeans) {
    return integerIn(record, key).value_or(absentMeans);
}

std::string textIn(const Node& record, std::string_view key) {
    return std::string(record.valueOf(key).value_or(std::string_view()));
}

std::string keywordIn(const Node& record, std::string_view key) {
    return std::string(trimmed(record.valueOf(key).value_or(std::string_view())));
}

void writeOptional(JsonWriter& json, std::string_view key, const std::optional<std::int64_t>& value) {
    if (value)
        json.value(key, *value);
    else
        json.null(key);
}

void OnceReporter::checkKeys(const Node& record, std::string_view where,
                             std::initializer_list<std::string_view> known,
                             std::initializer_list<std::string_view> repeatable) {
    const auto listed = [](std::initializer_list<std::string_view> keys, std::string_view key) {
        return std::find(keys.begin(), keys.end(), key) != keys.end();
    };
    std::map<std::string_view, int> firstLine;
    for (const Node& child : record.children()) {
        if (!child.isEntry())
            continue;
        const std::string key = dotted(child);
        if (!listed(known, child.key()))
            once("key " + std::string(where) + key, child.lineNumber(),
                 "unknown key " + quoteForMessage(key) + " in " + std::string(where),
                 "kept unchanged; reported once for the whole file");
        if (listed(repeatable, child.key()))
            continue;
        const auto [first, inserted] = firstLine.emplace(child.key(), child.lineNumber());
        if (!inserted)
            diagnostics_.warning(child.lineNumber(),
                                 quoteForMessage(key) + " given twice in one of the " + std::string(where) +
                                     " (first at line " + std::to_string(first->second) + ")",
                                 "kept unchanged; the first one is used");
    }
}

void OnceReporter::unknownRecord(const Node& record) {
    once("record " + std::string(record.key()), record.lineNumber(),
         "unknown record " + quoteForMessage(record.key()),
         "kept unchanged; reported once for the whole file");
}

void OnceReporter::strayLine(const Node& line) {
    once("stray " + dotted(line), line.lineNumber(), quoteForMessage(dotted(line)) + " outside any record",
         "kept unchanged and not read; reported once for the whole file");
}

void OnceReporter::once(std::string_view topic, int line, std::string message, std::string action) {
    if (seen_.first(topic))
        diagnostics_.warning(line, std::move(message), std::move(action));
}

std::string RecordReader::dottedKey(std::string_view key) const {
    return std::string(static_cast<std::size_t>(std::max(record_.level(), 0)) + 1, '.') + std::string(key);
}

bool RecordReader::readable(std::string_view key, const char* fallback) {
    const Node* line = record_.find(key);
    if (!line)
        return false;
    if (line->hasValue() && parseInteger(line->value()))
        return true;
    const std::string where = dottedKey(key) + " in " + std::string(name_);
    diagnostics_.warning(line->lineNumber(),
                         line->hasValue()
                             ? "value " + quoteForMessage(line->value()) + " of " + where + " is not a number"
                             : where + " has no value",
                         std::string("kept unchanged; ") + fallback);
    return false;
}

std::int64_t RecordReader::integer(std::string_view key, std::int64_t absentMeans) {
    const std::string fallback = formatDecimal(absentMeans) + " used";
    return readable(key, fallback.c_str()) ? *integerIn(record_, key) : absentMeans;
}

std::optional<std::int64_t> RecordReader::optionalInteger(std::string_view key) {
    return readable(key, "read as missing") ? integerIn(record_, key) : std::nullopt;
}

std::int64_t RecordReader::required(std::string_view key) {
    if (!has(key)) {
        diagnostics_.error(record_.lineNumber(), std::string(name_) + " without " + dottedKey(key),
                           "kept; read as 0");
        return 0;
    }
    return integer(key, 0);
}

void RecordWriter::integer(std::string_view key, std::int64_t value, std::int64_t absentMeans,
                           RecordEditor::Base base) {
    if (integerIn(source_, key, absentMeans) != value)
        editor_.setInteger(key, value, base, absentMeans);
}

void RecordWriter::required(std::string_view key, std::int64_t value) {
    if (source_.isEntry() && integerIn(source_, key, 0) == value)
        return;
    editor_.setInteger(key, value);
}

void RecordWriter::flag(std::string_view key, bool value, bool absentMeans) {
    const std::int64_t absent = absentMeans ? 1 : 0;
    if ((integerIn(source_, key, absent) != 0) != value)
        editor_.setInteger(key, value ? 1 : 0, RecordEditor::Base::Decimal, absent);
}

void RecordWriter::optionalInteger(std::string_view key, std::optional<std::int64_t> value) {
    if (integerIn(source_, key) == value)
        return;
    if (value)
        editor_.setInteger(key, *value);
    else
        editor_.remove(key);
}

void RecordWriter::optionalText(std::string_view key, std::string_view value) {
    if (textIn(source_, key) != value)
        editor_.setOptionalText(key, value);
}

void RecordWriter::optionalKeyword(std::string_view key, std::string_view value) {
    if (keywordIn(source_, key) != value)
        editor_.setOptionalText(key, value);
}

Node recordFrom(const Node& source, const Document& document, std::string_view keyword) {
    return source.isEntry() ? source : document.newRecord(keyword);
}

Node blockFrom(const Node& source, std::string_view key, const LineStyle& style) {
    return source.isEntry() ? source : Node::entry(1, key, std::nullopt, style);
}

void placeBlocks(Node& record, std::string_view key, std::vector<Node> blocks, std::string_view before) {
    std::vector<Node>& children = record.children();
    std::vector<Node> placed;
    placed.reserve(children.size() + blocks.size());
    std::size_t next = 0;
    std::optional<std::size_t> afterLastPlace;
    for (Node& child : children) {
        if (child.isEntry() && child.key() == key) {
            if (next < blocks.size())
                placed.push_back(std::move(blocks[next++]));
            afterLastPlace = placed.size();
            continue;
        }
        placed.push_back(std::move(child));
    }
    std::size_t at = placed.size();
    if (afterLastPlace) {
        at = *afterLastPlace;
    } else if (!before.empty()) {
        const auto first = std::find_if(placed.begin(), placed.end(), [before](const Node& child) {
            return child.isEntry() && child.key() == before;
        });
        at = static_cast<std::size_t>(first - placed.begin());
    }
    placed.insert(placed.begin() + static_cast<std::ptrdiff_t>(at),
                  std::make_move_iterator(blocks.begin() + static_cast<std::ptrdiff_t>(next)),
                  std::make_move_iterator(blocks.end()));
    children = std::move(placed);
}

void endLines(Node& record, Node::Ending lastEnding, const LineStyle& style) {
    std::vector<Node*> lines;
    collectLines(record, lines);
    const Node::Ending newline = Node::newlineOf(style);
    for (std::size_t i = 0; i + 1 < lines.size(); ++i)
        if (lines[i]->ending() == Node::Ending::None)
            lines[i]->setEnding(newline);
    lines.back()->setEnding(lastEnding);
}

FileVersion readVersion(const Document& document, OnceReporter& reporter) {
    const std::vector<const Node*> versions = document.records("version");
    if (versions.empty())
        return {};
    for (std::size_t i = 1; i < versions.size(); ++i)
        reporter.diagnostics().warning(versions[i]->lineNumber(), "second version record",
                                       "kept; the first one is used");
    const Node& version = *versions.front();
    reporter.checkKeys(version, "version records", {"major", "minor"});
    RecordReader reader(version, "the version record", reporter.diagnostics());
    return {reader.optionalInteger("major"), reader.optionalInteger("minor")};
}

void writeVersion(Document& document, const FileVersion& version) {
    Node* record = document.record("version");
    if (!record && !version.major && !version.minor)
        return;
    Node edited = record ? *record : document.newRecord("version");
    const Node source = record ? *record : Node();
    RecordWriter writer(edited, source, document.style());
    writer.optionalInteger("major", version.major);
    writer.optionalInteger("minor", version.minor);
    if (record) {
        *record = std::move(edited);
        return;
    }
    std::vector<Node> records;
    records.push_back(std::move(edited));
    document.replaceRecords("version", std::move(records));
}

void writeVersionJson(JsonWriter& json, const FileVersion& version) {
    json.beginObject("version");
    writeOptional(json, "major", version.major);
    writeOptional(json, "minor", version.minor);
    json.endObject();
}

void checkSection(const Document& document, std::string_view expected, std::string_view readAs,
                  Diagnostics& diagnostics) {
    if (!document.hasHeader() || document.section() == expected)
        return;
    diagnostics.warning(
        0, "section [" + std::string(document.section()) + "] instead of [" + std::string(expected) + "]",
        "read as " + std::string(readAs));
}

} // namespace stellwerk::cs2config::accessories
