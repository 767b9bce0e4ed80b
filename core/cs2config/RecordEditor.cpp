#include "cs2config/RecordEditor.h"

#include "cs2config/Values.h"

#include <algorithm>

namespace stellwerk::cs2config {

namespace {

// The file's last line may lack a line end; a line inserted right after it inherits that instead.
void passEnding(Node& before, Node& inserted) {
    Node& last = before.lastLine();
    if (last.ending() != Node::Ending::None)
        return;
    last.setEnding(inserted.ending());
    inserted.setEnding(Node::Ending::None);
}

} // namespace

// The record's own ".key" line (not a line nested one level too deep in a damaged file).
Node* RecordEditor::ownLine(std::string_view key) {
    for (Node& child : record_.children())
        if (child.isEntry() && child.level() == childLevel() && child.key() == key)
            return &child;
    return nullptr;
}

void RecordEditor::setText(std::string_view key, std::string_view value) {
    if (Node* line = ownLine(key))
        line->setValue(value);
    else
        insertEntry(key, value);
}

void RecordEditor::setOptionalText(std::string_view key, std::string_view value) {
    if (ownLine(key) || !value.empty())
        setText(key, value);
}

void RecordEditor::setInteger(std::string_view key, std::int64_t value, Base base,
                              std::optional<std::int64_t> absentMeans) {
    const std::string text =
        base == Base::Hex ? formatHex(static_cast<std::uint64_t>(value)) : formatDecimal(value);
    Node* line = ownLine(key);
    if (!line) {
        if (!absentMeans || *absentMeans != value)
            insertEntry(key, text);
        return;
    }
    if (line->hasValue() && parseInteger(line->value()) == value)
        return;
    line->setValue(text);
}

void RecordEditor::remove(std::string_view key) {
    auto& children = record_.children();
    children.erase(std::remove_if(children.begin(), children.end(),
                                  [this, key](const Node& child) {
                                      return child.isEntry() && child.level() == childLevel() &&
                                             child.key() == key;
                                  }),
                   children.end());
}

Node& RecordEditor::appendBlock(std::string_view key) {
    auto& children = record_.children();
    Node block = Node::entry(childLevel(), key, std::nullopt, style_);
    passEnding(children.empty() ? record_ : children.back(), block);
    children.push_back(std::move(block));
    return children.back();
}

Node& RecordEditor::insertEntry(std::string_view key, std::string_view value) {
    auto& children = record_.children();
    auto position = children.begin();
    for (auto it = children.begin(); it != children.end(); ++it)
        if (it->isEntry() && it->level() == childLevel() && it->hasValue() && it->children().empty())
            position = it + 1;
    Node entry = Node::entry(childLevel(), key, value, style_);
    if (position != children.begin())
        passEnding(*(position - 1), entry);
    else if (children.empty())
        passEnding(record_, entry);
    return *children.insert(position, std::move(entry));
}

} // namespace stellwerk::cs2config
