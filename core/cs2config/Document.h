#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Node.h"

#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// A .cs2 file as a tree of its lines: "[section]" header, records at column 0 and their ".key" and
// "..key" lines. Reading then writing an unchanged document gives the same bytes; editing one value
// changes one line.
class Document {
public:
    // Lines nested deeper than this are kept verbatim and reported (bounds the tree depth).
    static constexpr int maxLevel = 16;

    static Document parse(std::string_view bytes, Diagnostics& diagnostics);
    // An empty document with a "[section]" header written in the given style.
    static Document create(std::string_view section, LineStyle style = {});

    std::string serialize() const;

    bool hasHeader() const { return hasHeader_; }
    // The header's name ("lokomotive"), empty when the file has no header.
    std::string_view section() const { return section_; }
    // True when the file is a .cs2 file at all: a header or at least one "key=value" or ".key" line
    // (a bare word is not enough: any text file has those).
    bool isConfiguration() const { return hasHeader() || entryCount_ > 0; }
    const LineStyle& style() const { return style_; }

    // The top level in file order: junk before the header, the header, records (level-0 entries).
    const std::vector<Node>& topLevel() const { return root_.children(); }
    std::vector<Node>& topLevel() { return root_.children(); }
    const Node& root() const { return root_; }

    // The level-0 records with this keyword ("lokomotive", "element", ...), in file order.
    // A stray ".keyword" line outside any record is not a record.
    std::vector<const Node*> records(std::string_view keyword) const;
    std::vector<Node*> records(std::string_view keyword);
    // The first record with this keyword, or null.
    const Node* record(std::string_view keyword) const;
    Node* record(std::string_view keyword);

    // Replaces the records with this keyword by the given ones: the n-th new record takes the place
    // of the n-th old one, further ones follow the last old one (or go at the end when there was
    // none). Other records and lines keep their place.
    void replaceRecords(std::string_view keyword, std::vector<Node> records);
    // A new record line "keyword" in this document's style.
    Node newRecord(std::string_view keyword) const;

private:
    friend class DocumentParser;
    Document() = default;

    Node root_;
    bool hasHeader_ = false;
    std::string section_;
    LineStyle style_;
    std::size_t entryCount_ = 0;
};

} // namespace stellwerk::cs2config
