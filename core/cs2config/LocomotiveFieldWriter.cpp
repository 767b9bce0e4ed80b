#include "cs2config/LocomotiveFieldWriter.h"

#include "cs2config/Values.h"

#include <algorithm>
#include <iterator>
#include <optional>

namespace stellwerk::cs2config::loco {

namespace {

bool writtenInHex(const Node& line) {
    const std::string_view value = trimmed(line.value());
    const std::string_view digits = !value.empty() && value.front() == '-' ? value.substr(1) : value;
    return digits.size() > 1 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X');
}

void collectLines(Node& node, std::vector<Node*>& lines) {
    if (node.kind() != Node::Kind::Root)
        lines.push_back(&node);
    for (Node& child : node.children())
        collectLines(child, lines);
}

// Only the last line may lack a line end (the file's last line); any other line without one gets the
// style's line end, and the last line then takes over the missing one.
void endAllButLast(const std::vector<Node*>& lines, const LineStyle& style) {
    const Node::Ending ending = Node::newlineOf(style);
    bool unended = false;
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
        if (lines[i]->ending() != Node::Ending::None)
            continue;
        lines[i]->setEnding(ending);
        unended = true;
    }
    if (unended)
        lines.back()->setEnding(Node::Ending::None);
}

} // namespace

FieldWriter::FieldWriter(Node& record, const LineStyle& style, bool fresh, TextCoding coding)
    : record_(record), editor_(record, style), fresh_(fresh), coding_(coding) {}

void FieldWriter::writeNumber(std::string_view key, const Node* line, std::int64_t value, Base base) {
    const bool hex = line && line->hasValue() ? writtenInHex(*line) : base == Base::Hex;
    editor_.setText(key,
                    hex && value >= 0 ? formatHex(static_cast<std::uint64_t>(value)) : formatDecimal(value));
}

void FieldWriter::text(std::string_view key, std::string_view value, Presence presence) {
    const Node* line = record_.find(key);
    if (readText(line, coding_) == value && (line || !forced(presence)))
        return;
    editor_.setText(key, coding_ == TextCoding::Cs3Escaped ? cs3Escape(value) : std::string(value));
}

void FieldWriter::direction(std::string_view key, TravelDirection direction) {
    if (direction == TravelDirection::Unknown)
        return;
    const Node* line = record_.find(key);
    if (readDirection(line).value == direction)
        return;
    editor_.setText(key, direction == TravelDirection::Forward ? "0" : "1");
}

void FieldWriter::decoder(std::string_view key, LocomotiveDecoder decoder, std::string_view unknownText) {
    const Node* line = record_.find(key);
    const std::string current(trimmed(readText(line, coding_)));
    const LocomotiveDecoder read = decoderFromName(current);
    const bool same = read == decoder && (decoder != LocomotiveDecoder::Unknown || current == unknownText);
    if (same && (line || !fresh_))
        return;
    editor_.setText(key, decoder == LocomotiveDecoder::Unknown ? unknownText : decoderName(decoder));
}

std::string_view keyInUse(const Node& record, std::string_view key, std::string_view alternative) {
    return !record.find(key) && record.find(alternative) ? alternative : key;
}

namespace {

void replaceEntries(std::vector<Node>& nodes, std::initializer_list<std::string_view> keys,
                    std::vector<Node> replacements) {
    const auto isReplaced = [&keys](const Node& node) {
        return node.isEntry() && std::find(keys.begin(), keys.end(), node.key()) != keys.end();
    };
    std::vector<Node> kept;
    kept.reserve(nodes.size() + replacements.size());
    std::size_t next = 0;
    std::optional<std::size_t> afterLastPlace;
    for (Node& node : nodes) {
        if (!isReplaced(node)) {
            kept.push_back(std::move(node));
            continue;
        }
        if (next < replacements.size())
            kept.push_back(std::move(replacements[next++]));
        afterLastPlace = kept.size();
    }
    const auto insertAt =
        afterLastPlace ? kept.begin() + static_cast<std::ptrdiff_t>(*afterLastPlace) : kept.end();
    kept.insert(insertAt, std::make_move_iterator(replacements.begin() + static_cast<std::ptrdiff_t>(next)),
                std::make_move_iterator(replacements.end()));
    nodes = std::move(kept);
}

} // namespace

void replaceBlocks(Node& record, std::initializer_list<std::string_view> keys, std::vector<Node> blocks) {
    replaceEntries(record.children(), keys, std::move(blocks));
}

void keepFinalEnding(Node& record, const LineStyle& style) {
    std::vector<Node*> lines;
    collectLines(record, lines);
    endAllButLast(lines, style);
}

} // namespace stellwerk::cs2config::loco
