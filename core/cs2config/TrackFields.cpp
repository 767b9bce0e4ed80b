#include "cs2config/TrackFields.h"

#include "cs2config/Text.h"
#include "cs2config/Values.h"

#include <algorithm>
#include <vector>

namespace stellwerk::cs2config {

namespace {

bool contains(std::span<const std::string_view> list, std::string_view word) {
    return std::find(list.begin(), list.end(), word) != list.end();
}

} // namespace

const Node* findField(const Node& record, std::string_view key) {
    for (const Node& child : record.children())
        if (child.isEntry() && child.level() == record.level() + 1 && child.key() == key)
            return &child;
    return nullptr;
}

Node* findField(Node& record, std::string_view key) {
    return const_cast<Node*>(findField(static_cast<const Node&>(record), key));
}

int TrackFieldReader::line(std::string_view key) const {
    const Node* entry = findField(record_, key);
    return entry ? entry->lineNumber() : record_.lineNumber();
}

void TrackFieldReader::warn(std::string_view key, std::string message, std::string action) const {
    if (diagnostics_)
        diagnostics_->warning(line(key), std::move(message), std::move(action));
}

std::optional<std::int64_t> TrackFieldReader::optionalInteger(std::string_view key, std::int64_t min,
                                                              std::int64_t max,
                                                              std::string_view fallback) const {
    const Node* entry = findField(record_, key);
    if (!entry)
        return std::nullopt;
    const std::string_view value = entry->hasValue() ? entry->value() : std::string_view();
    const std::optional<std::int64_t> number = parseInteger(value);
    const std::string subject = std::string(what_) + " ." + std::string(key) + " ";
    const std::string action = std::string(fallback) + "; the line is kept as it is";
    if (!number) {
        warn(key, subject + quoteForMessage(value) + " is not a number", action);
        return std::nullopt;
    }
    if (*number < min || *number > max) {
        warn(key,
             subject + formatDecimal(*number) + " is outside " + formatDecimal(min) + ".." +
                 formatDecimal(max),
             action);
        return std::nullopt;
    }
    return number;
}

std::int64_t TrackFieldReader::integer(std::string_view key, std::int64_t absent, std::int64_t min,
                                       std::int64_t max) const {
    return optionalInteger(key, min, max, formatDecimal(absent) + " used").value_or(absent);
}

std::string TrackFieldReader::text(std::string_view key) const {
    const Node* entry = findField(record_, key);
    return entry && entry->hasValue() ? std::string(entry->value()) : std::string();
}

std::string TrackFieldReader::word(std::string_view key) const {
    return std::string(trimmed(text(key)));
}

void TrackFieldWriter::setText(std::string_view key, std::string_view value) {
    // A value is one line: a line feed would start a new line, a carriage return at its end would be
    // read back as part of a CR LF line end.
    std::string line(value);
    std::replace(line.begin(), line.end(), '\n', ' ');
    if (!line.empty() && line.back() == '\r')
        line.back() = ' ';
    if (Node* existing = findField(record_, key))
        existing->setValue(line);
    else
        add(key, line, false);
}

void TrackFieldWriter::setOptionalText(std::string_view key, std::string_view value) {
    if (findField(record_, key) || !value.empty())
        setText(key, value);
}

void TrackFieldWriter::setInteger(std::string_view key, std::int64_t value, Base base,
                                  std::optional<std::int64_t> absentMeans) {
    const std::string text =
        base == Base::Hex ? formatHex(static_cast<std::uint64_t>(value)) : formatDecimal(value);
    Node* line = findField(record_, key);
    if (!line) {
        if (absentMeans != value)
            add(key, text, false);
        return;
    }
    if (!line->hasValue() || parseInteger(line->value()) != value)
        line->setValue(text);
}

void TrackFieldWriter::setIntegerFirst(std::string_view key, std::int64_t value, Base base,
                                       std::int64_t absentMeans) {
    if (findField(record_, key) || value == absentMeans || !canPutFirst()) {
        setInteger(key, value, base, absentMeans);
        return;
    }
    add(key, base == Base::Hex ? formatHex(static_cast<std::uint64_t>(value)) : formatDecimal(value), true);
}

void TrackFieldWriter::remove(std::string_view key) {
    auto& children = record_.children();
    const int level = record_.level() + 1;
    children.erase(std::remove_if(children.begin(), children.end(),
                                  [key, level](const Node& child) {
                                      return child.isEntry() && child.level() == level && child.key() == key;
                                  }),
                   children.end());
}

// A line put first keeps every line below it in place only when the record's first entry is one of
// its own keys: misnested deeper lines before it would be read as belonging to the new line.
bool TrackFieldWriter::canPutFirst() const {
    for (const Node& child : record_.children())
        if (child.isEntry())
            return child.level() == record_.level() + 1;
    return false;
}

void TrackFieldWriter::add(std::string_view key, std::string_view value, bool first) {
    Node entry = Node::entry(record_.level() + 1, key, value, style_);
    auto& children = record_.children();
    if (first) {
        children.insert(children.begin(), std::move(entry));
        return;
    }
    // The file's last line may lack a line end; a line added after it takes that over.
    Node& last = record_.lastLine();
    if (last.ending() == Node::Ending::None) {
        last.setEnding(entry.ending());
        entry.setEnding(Node::Ending::None);
    }
    children.push_back(std::move(entry));
}

void checkRecordKeys(const Node& record, std::span<const std::string_view> known, std::string_view what,
                     ReportOnce& unknownKeys, Diagnostics& diagnostics) {
    std::vector<const Node*> seen;
    for (const Node& child : record.children()) {
        if (!child.isEntry() || child.level() != record.level() + 1)
            continue; // misnested lines are reported by the parser
        const std::string_view key = child.key();
        if (!contains(known, key)) {
            if (unknownKeys.first(key))
                diagnostics.warning(child.lineNumber(),
                                    "unknown " + std::string(what) + " key ." + std::string(key) +
                                        " (reported once)",
                                    "kept unchanged");
            continue;
        }
        const auto earlier =
            std::find_if(seen.begin(), seen.end(), [key](const Node* node) { return node->key() == key; });
        if (earlier != seen.end())
            diagnostics.warning(child.lineNumber(),
                                std::string(what) + " has ." + std::string(key) + " twice (also line " +
                                    std::to_string((*earlier)->lineNumber()) + ")",
                                "the first one is used; both are kept");
        else
            seen.push_back(&child);
    }
}

} // namespace stellwerk::cs2config
