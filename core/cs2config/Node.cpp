#include "cs2config/Node.h"

namespace stellwerk::cs2config {

Node Node::entry(int level, std::string_view key, std::optional<std::string_view> value,
                 const LineStyle& style) {
    Node node;
    node.kind_ = Kind::Entry;
    node.level_ = static_cast<std::int16_t>(level);
    node.raw_ = level > 0 ? style.indent : std::string();
    node.raw_.append(static_cast<std::size_t>(level), '.');
    node.keyStart_ = static_cast<std::uint32_t>(node.raw_.size());
    node.keyLength_ = static_cast<std::uint32_t>(key.size());
    node.raw_ += key;
    if (value) {
        node.raw_ += '=';
        node.hasValue_ = true;
        node.valueStart_ = static_cast<std::uint32_t>(node.raw_.size());
        node.raw_ += *value;
    }
    node.ending_ = newlineOf(style);
    return node;
}

Node Node::fromLine(std::string raw, Ending ending, int lineNumber) {
    Node node;
    node.raw_ = std::move(raw);
    node.ending_ = ending;
    node.lineNumber_ = lineNumber;
    node.kind_ = Kind::Verbatim;
    return node;
}

std::string_view Node::value() const {
    if (!hasValue_)
        return {};
    return text().substr(valueStart_);
}

void Node::setValue(std::string_view value) {
    if (hasValue_ && this->value() == value)
        return;
    std::string prefix(text().substr(0, hasValue_ ? valueStart_ : keyStart_ + keyLength_));
    if (!hasValue_) {
        prefix += '=';
        hasValue_ = true;
    }
    valueStart_ = static_cast<std::uint32_t>(prefix.size());
    raw_ = std::move(prefix);
    raw_ += value;
    decoded_.clear();
}

const Node* Node::find(std::string_view key) const {
    for (const Node& child : children_)
        if (child.isEntry() && child.key() == key)
            return &child;
    return nullptr;
}

Node* Node::find(std::string_view key) {
    return const_cast<Node*>(static_cast<const Node*>(this)->find(key));
}

std::optional<std::string_view> Node::valueOf(std::string_view key) const {
    const Node* child = find(key);
    if (!child || !child->hasValue())
        return std::nullopt;
    return child->value();
}

std::vector<const Node*> Node::all(std::string_view key) const {
    std::vector<const Node*> found;
    for (const Node& child : children_)
        if (child.isEntry() && child.key() == key)
            found.push_back(&child);
    return found;
}

std::vector<Node*> Node::all(std::string_view key) {
    std::vector<Node*> found;
    for (Node& child : children_)
        if (child.isEntry() && child.key() == key)
            found.push_back(&child);
    return found;
}

const Node& Node::lastLine() const {
    const Node* last = this;
    while (!last->children_.empty())
        last = &last->children_.back();
    return *last;
}

Node& Node::lastLine() {
    return const_cast<Node&>(static_cast<const Node*>(this)->lastLine());
}

void Node::appendTo(std::string& out) const {
    if (kind_ != Kind::Root) {
        out += raw_;
        if (ending_ == Ending::Lf)
            out += '\n';
        else if (ending_ == Ending::CrLf)
            out += "\r\n";
    }
    for (const Node& child : children_)
        child.appendTo(out);
}

std::string Node::serialize() const {
    std::string out;
    appendTo(out);
    return out;
}

} // namespace stellwerk::cs2config
