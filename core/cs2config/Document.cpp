#include "cs2config/Document.h"

#include "cs2config/DocumentParser.h"

#include <utility>

namespace stellwerk::cs2config {

namespace {

// A line that had no line end because it was the last one gets one when lines follow it.
void endLastLine(Node& node, const LineStyle& style) {
    Node& last = node.lastLine();
    if (last.kind() != Node::Kind::Root && last.ending() == Node::Ending::None)
        last.setEnding(Node::newlineOf(style));
}

bool isRecord(const Node& node, std::string_view keyword) {
    return node.isEntry() && node.level() == 0 && node.key() == keyword;
}

} // namespace

Document Document::parse(std::string_view bytes, Diagnostics& diagnostics) {
    return DocumentParser(bytes, diagnostics).parse();
}

Document Document::create(std::string_view section, LineStyle style) {
    Document document;
    Diagnostics ignored;
    document = parse("[" + std::string(section) + "]" + style.newline, ignored);
    document.style_ = std::move(style);
    return document;
}

std::string Document::serialize() const {
    return root_.serialize();
}

Node Document::newRecord(std::string_view keyword) const {
    return Node::entry(0, keyword, std::nullopt, style_);
}

std::vector<const Node*> Document::records(std::string_view keyword) const {
    std::vector<const Node*> found;
    for (const Node& node : root_.children())
        if (isRecord(node, keyword))
            found.push_back(&node);
    return found;
}

std::vector<Node*> Document::records(std::string_view keyword) {
    std::vector<Node*> found;
    for (Node& node : root_.children())
        if (isRecord(node, keyword))
            found.push_back(&node);
    return found;
}

const Node* Document::record(std::string_view keyword) const {
    for (const Node& node : root_.children())
        if (isRecord(node, keyword))
            return &node;
    return nullptr;
}

Node* Document::record(std::string_view keyword) {
    return const_cast<Node*>(std::as_const(*this).record(keyword));
}

void Document::replaceRecords(std::string_view keyword, std::vector<Node> records) {
    std::vector<Node>& top = root_.children();
    const bool noFinalNewline = !top.empty() && root_.lastLine().ending() == Node::Ending::None;
    std::vector<Node> kept;
    kept.reserve(top.size() + records.size());
    std::size_t next = 0;
    std::size_t afterLastSlot = 0;
    for (Node& node : top) {
        // Only records (level 0): a stray ".keyword" line outside any record stays where it is.
        if (!isRecord(node, keyword)) {
            kept.push_back(std::move(node));
            continue;
        }
        // The n-th new record takes the n-th old one's place, so records split by others stay put.
        if (next < records.size())
            kept.push_back(std::move(records[next++]));
        afterLastSlot = kept.size();
    }
    if (afterLastSlot == 0)
        afterLastSlot = kept.size();
    if (next < records.size()) {
        if (afterLastSlot > 0)
            endLastLine(kept[afterLastSlot - 1], style_);
        kept.insert(kept.begin() + static_cast<std::ptrdiff_t>(afterLastSlot),
                    std::make_move_iterator(records.begin() + static_cast<std::ptrdiff_t>(next)),
                    std::make_move_iterator(records.end()));
    }
    top = std::move(kept);
    // Whatever now comes last keeps the file's own ending; anything before it needs a line end.
    for (std::size_t i = 0; i + 1 < top.size(); ++i)
        endLastLine(top[i], style_);
    // A file without a final newline keeps that property whatever now comes last.
    if (noFinalNewline && !top.empty()) {
        endLastLine(top.back(), style_);
        root_.lastLine().setEnding(Node::Ending::None);
    }
}

} // namespace stellwerk::cs2config
