#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"

#include <string_view>

namespace stellwerk::cs2config {
class LineClassifier;
}

namespace stellwerk::cs2config {

// Builds a Document from bytes in one pass: splits lines, reads each (UTF-8, Latin-1 fallback),
// nests entries by their dots and reports every line it could not read.
class DocumentParser {
public:
    DocumentParser(std::string_view bytes, Diagnostics& diagnostics);
    Document parse();

private:
    struct RawLine {
        std::string_view bytes;
        Node::Ending ending;
    };

    std::vector<RawLine> splitLines() const;
    Document keepBinary(const std::vector<RawLine>& lines);
    std::size_t headerIndex(const std::vector<RawLine>& lines);
    void readHeaderAfterJunk(Node& node, LineClassifier& classifier);
    Node readLine(const RawLine& line, int lineNumber, bool beforeHeader);
    void attach(Node node);
    void noteStyle(const Node& node, Node::Ending ending);

    std::string_view bytes_;
    Diagnostics& diagnostics_;
    Document document_;
    std::vector<Node*> open_; // the chain of nodes the next line may nest under
    bool styleKnown_ = false;
    bool headerAfterJunk_ = false; // the header line has junk in front of its "[section]"
};

} // namespace stellwerk::cs2config
