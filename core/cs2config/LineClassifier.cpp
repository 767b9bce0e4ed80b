#include "cs2config/LineClassifier.h"

#include "cs2config/Text.h"

namespace stellwerk::cs2config {

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

std::string_view trimRight(std::string_view text) {
    while (!text.empty() && (isBlank(text.back()) || text.back() == '\r'))
        text.remove_suffix(1);
    return text;
}

bool hasControlBytes(std::string_view text) {
    for (char c : text)
        if ((static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\r') || c == 0x7F)
            return true;
    return false;
}

} // namespace

bool LineClassifier::isKeyCharacter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

bool LineClassifier::isHeader(std::string_view line) {
    line = trimRight(line);
    if (line.size() < 3 || line.front() != '[' || line.back() != ']')
        return false;
    for (char c : line.substr(1, line.size() - 2))
        if (!isKeyCharacter(c))
            return false;
    return true;
}

std::size_t LineClassifier::headerAfterJunk(std::string_view line) {
    line = trimRight(line);
    const std::size_t bracket = line.rfind('[');
    if (bracket == std::string_view::npos || bracket == 0 || !isHeader(line.substr(bracket)))
        return std::string_view::npos;
    const std::string_view junk = line.substr(0, bracket);
    if (junk.find('\0') != std::string_view::npos || junk.find(']') != std::string_view::npos)
        return std::string_view::npos;
    std::size_t key = junk.find_first_not_of(" \t.");
    while (key < junk.size() && isKeyCharacter(junk[key]))
        ++key;
    if (key < junk.size() && junk[key] == '=') // an entry whose value ends in brackets
        return std::string_view::npos;
    return bracket;
}

bool LineClassifier::classifyHeaderAfterJunk() {
    const std::string_view text = node_.text();
    const std::size_t bracket = headerAfterJunk(text);
    if (bracket == std::string_view::npos)
        return false;
    node_.kind_ = Node::Kind::Header;
    node_.level_ = 0;
    node_.keyStart_ = static_cast<std::uint32_t>(bracket + 1);
    node_.keyLength_ = static_cast<std::uint32_t>(trimRight(text).size() - bracket - 2);
    return true;
}

void LineClassifier::decodeLatin1() {
    node_.decoded_ = latin1ToUtf8(node_.raw_);
}

LineClassifier::Result LineClassifier::classify(int maxLevel) {
    const std::string_view text = node_.text();
    if (isHeader(text)) {
        node_.kind_ = Node::Kind::Header;
        node_.level_ = 0;
        node_.keyStart_ = 1;
        node_.keyLength_ = static_cast<std::uint32_t>(trimRight(text).size() - 2);
        return Result::Header;
    }
    std::size_t start = 0;
    while (start < text.size() && isBlank(text[start]))
        ++start;
    if (trimRight(text.substr(start)).empty())
        return Result::Blank;
    if (hasControlBytes(text))
        return Result::Unreadable;
    return classifyEntry(start, maxLevel);
}

LineClassifier::Result LineClassifier::classifyEntry(std::size_t start, int maxLevel) {
    const std::string_view text = node_.text();
    std::size_t keyStart = start;
    while (keyStart < text.size() && text[keyStart] == '.')
        ++keyStart;
    const auto level = static_cast<int>(keyStart - start);
    std::size_t keyEnd = keyStart;
    while (keyEnd < text.size() && isKeyCharacter(text[keyEnd]))
        ++keyEnd;
    if (keyEnd == keyStart)
        return Result::Unreadable;
    const bool hasValue = keyEnd < text.size() && text[keyEnd] == '=';
    if (!hasValue && !trimRight(text.substr(keyEnd)).empty())
        return Result::Unreadable;
    if (level > maxLevel)
        return Result::TooDeep;
    node_.kind_ = Node::Kind::Entry;
    node_.level_ = static_cast<std::int16_t>(level);
    node_.keyStart_ = static_cast<std::uint32_t>(keyStart);
    node_.keyLength_ = static_cast<std::uint32_t>(keyEnd - keyStart);
    node_.hasValue_ = hasValue;
    node_.valueStart_ = static_cast<std::uint32_t>(hasValue ? keyEnd + 1 : keyEnd);
    return Result::Entry;
}

std::string LineClassifier::hint() const {
    const std::string_view text = node_.text();
    if (text.find(']') != std::string_view::npos || text.find('[') != std::string_view::npos)
        return " (a damaged section header?)";
    if (hasControlBytes(text))
        return " (control characters: binary data?)";
    return {};
}

} // namespace stellwerk::cs2config
