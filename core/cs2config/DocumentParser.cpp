#include "cs2config/DocumentParser.h"

#include "cs2config/LineClassifier.h"
#include "cs2config/Text.h"

namespace stellwerk::cs2config {

DocumentParser::DocumentParser(std::string_view bytes, Diagnostics& diagnostics)
    : bytes_(bytes), diagnostics_(diagnostics) {}

Document DocumentParser::parse() {
    const std::vector<RawLine> lines = splitLines();
    const std::size_t header = headerIndex(lines);
    if (header == lines.size() && bytes_.find('\0') != std::string_view::npos)
        return keepBinary(lines);
    if (header != lines.size() && header > 0)
        diagnostics_.warning(1, std::to_string(header) + " line(s) before the [section] header",
                             "kept unchanged and not read");
    open_ = {&document_.root_};
    for (std::size_t i = 0; i < lines.size(); ++i)
        attach(readLine(lines[i], static_cast<int>(i) + 1, header != lines.size() && i < header));
    if (!document_.hasHeader_) {
        if (document_.entryCount_ == 0)
            diagnostics_.error(0, "not a .cs2 file: no [section] header and no records", "nothing read");
        else
            diagnostics_.warning(0, "no [section] header", "read the records without one");
    }
    return std::move(document_);
}

// Bytes with NUL and no header are binary data, not a damaged .cs2 file: one report, not one per line.
Document DocumentParser::keepBinary(const std::vector<RawLine>& lines) {
    for (std::size_t i = 0; i < lines.size(); ++i)
        document_.root_.children().push_back(
            Node::fromLine(std::string(lines[i].bytes), lines[i].ending, static_cast<int>(i) + 1));
    diagnostics_.error(0, "binary data (NUL bytes, no [section] header): not a .cs2 text file",
                       "nothing read");
    return std::move(document_);
}

std::vector<DocumentParser::RawLine> DocumentParser::splitLines() const {
    std::vector<RawLine> lines;
    std::size_t start = 0;
    while (start < bytes_.size()) {
        const std::size_t end = bytes_.find('\n', start);
        if (end == std::string_view::npos) {
            lines.push_back({bytes_.substr(start), Node::Ending::None});
            break;
        }
        const bool crlf = end > start && bytes_[end - 1] == '\r';
        lines.push_back({bytes_.substr(start, end - start - (crlf ? 1 : 0)),
                         crlf ? Node::Ending::CrLf : Node::Ending::Lf});
        start = end + 1;
    }
    return lines;
}

// A clean "[section]" line; failing that, the first line that ends in one after some junk.
std::size_t DocumentParser::headerIndex(const std::vector<RawLine>& lines) {
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (LineClassifier::isHeader(lines[i].bytes))
            return i;
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (LineClassifier::headerAfterJunk(lines[i].bytes) != std::string_view::npos) {
            headerAfterJunk_ = true;
            return i;
        }
    return lines.size();
}

void DocumentParser::readHeaderAfterJunk(Node& node, LineClassifier& classifier) {
    if (!classifier.classifyHeaderAfterJunk())
        return;
    const std::string_view text = node.text();
    const std::string junk(text.substr(0, text.rfind('[')));
    diagnostics_.warning(node.lineNumber(),
                         quoteForMessage(junk) + " in front of the section header [" +
                             std::string(node.key()) + "]",
                         "read as the header; the text in front of it is kept unchanged");
}

Node DocumentParser::readLine(const RawLine& line, int lineNumber, bool beforeHeader) {
    Node node = Node::fromLine(std::string(line.bytes), line.ending, lineNumber);
    LineClassifier classifier(node);
    if (!isValidUtf8(line.bytes)) {
        classifier.decodeLatin1();
        diagnostics_.warning(lineNumber, "not valid UTF-8", "read as Latin-1, written back unchanged");
    }
    if (beforeHeader)
        return node;
    if (headerAfterJunk_ && !document_.hasHeader_) {
        readHeaderAfterJunk(node, classifier);
        if (node.kind() == Node::Kind::Header) {
            noteStyle(node, line.ending);
            return node;
        }
    }
    const LineClassifier::Result result = classifier.classify(Document::maxLevel);
    if (result == LineClassifier::Result::Unreadable)
        diagnostics_.warning(lineNumber,
                             "unreadable line " + quoteForMessage(node.text()) + classifier.hint(),
                             "kept unchanged and not read");
    else if (result == LineClassifier::Result::TooDeep)
        diagnostics_.warning(lineNumber,
                             "line nested deeper than " + std::to_string(Document::maxLevel) + " levels",
                             "kept unchanged and not read");
    noteStyle(node, line.ending);
    return node;
}

void DocumentParser::noteStyle(const Node& node, Node::Ending ending) {
    if (node.kind() == Node::Kind::Header && !document_.hasHeader_)
        document_.style_.newline = ending == Node::Ending::CrLf ? "\r\n" : "\n";
    if (styleKnown_ || !node.isEntry() || node.level() == 0)
        return;
    const std::string_view text = node.text();
    document_.style_.indent = std::string(text.substr(0, text.find('.')));
    styleKnown_ = true;
}

void DocumentParser::attach(Node node) {
    if (node.kind() == Node::Kind::Header) {
        if (document_.hasHeader_)
            diagnostics_.warning(node.lineNumber(), "second section header " + quoteForMessage(node.text()),
                                 "kept; the records after it are read as part of this file");
        else
            document_.section_ = std::string(node.key());
        document_.hasHeader_ = true;
        open_.resize(1);
        open_.front()->children().push_back(std::move(node));
        return;
    }
    if (!node.isEntry()) {
        open_.back()->children().push_back(std::move(node));
        return;
    }
    if (node.level() > 0 || node.hasValue())
        ++document_.entryCount_;
    while (open_.back()->level() >= node.level())
        open_.pop_back();
    Node* parent = open_.back();
    if (parent->kind() == Node::Kind::Entry && node.level() > parent->level() + 1)
        diagnostics_.warning(node.lineNumber(),
                             "'" + std::string(node.key()) + "' is nested without its block",
                             "kept under the line before it");
    parent->children().push_back(std::move(node));
    open_.push_back(&parent->children().back());
}

} // namespace stellwerk::cs2config
