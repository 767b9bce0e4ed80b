#pragma once

#include "cs2config/Node.h"

#include <string>
#include <string_view>

namespace stellwerk::cs2config {

// Reads one line of a .cs2 file: header, entry ("key", ".key=value", "..key") or something else.
class LineClassifier {
public:
    enum class Result { Header, Entry, Blank, Unreadable, TooDeep };

    explicit LineClassifier(Node& node) : node_(node) {}

    static bool isHeader(std::string_view line);
    // Where the "[section]" of a header with junk in front of it ("Bau [magnetartikel]") starts;
    // npos for any other line (a clean header, an entry such as ".name=Gleis [3]", plain text).
    static std::size_t headerAfterJunk(std::string_view line);
    static bool isKeyCharacter(char c);

    void decodeLatin1();
    Result classify(int maxLevel);
    // Reads the line as a header with junk in front of it; false when it is not one.
    bool classifyHeaderAfterJunk();
    // A hint about what an unreadable line probably was, e.g. " (a damaged section header?)".
    std::string hint() const;

private:
    Result classifyEntry(std::size_t start, int maxLevel);

    Node& node_;
};

} // namespace stellwerk::cs2config
