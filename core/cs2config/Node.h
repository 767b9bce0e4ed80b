#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// How a file writes its lines (indent before the dots, line end), so that added lines look like
// the ones around them.
struct LineStyle {
    std::string indent = " ";
    std::string newline = "\n";
};

// One line of a .cs2 file, kept exactly as read, and the lines nested under it. A record keyword
// ("lokomotive") is level 0, ".key" level 1, "..key" level 2; blank and unreadable lines are kept
// verbatim where they stood so that writing reproduces the file byte for byte.
class Node {
public:
    enum class Kind : std::uint8_t { Root, Header, Entry, Verbatim };
    enum class Ending : std::uint8_t { None, Lf, CrLf };

    Node() = default;
    // A new entry line written in the given style: "<indent><dots>key" or "...key=value".
    static Node entry(int level, std::string_view key, std::optional<std::string_view> value,
                      const LineStyle& style);
    // A line read from a file; classify() sets the kind and the key/value positions.
    static Node fromLine(std::string raw, Ending ending, int lineNumber);
    // The line end the style writes.
    static Ending newlineOf(const LineStyle& style) {
        return style.newline == "\r\n" ? Ending::CrLf : Ending::Lf;
    }

    Kind kind() const { return kind_; }
    bool isEntry() const { return kind_ == Kind::Entry; }
    int level() const { return level_; }
    int lineNumber() const { return lineNumber_; }
    Ending ending() const { return ending_; }
    void setEnding(Ending ending) { ending_ = ending; }

    std::string_view raw() const { return raw_; }
    // The line as text: the raw bytes, or their Latin-1 reading when they were not valid UTF-8.
    std::string_view text() const { return decoded_.empty() ? std::string_view(raw_) : decoded_; }
    std::string_view key() const { return text().substr(keyStart_, keyLength_); }
    bool hasValue() const { return hasValue_; }
    std::string_view value() const;

    // Rewrites this line's value and nothing else of the file.
    void setValue(std::string_view value);

    const std::vector<Node>& children() const { return children_; }
    std::vector<Node>& children() { return children_; }

    // The first child entry with this key, or null.
    const Node* find(std::string_view key) const;
    Node* find(std::string_view key);
    // The value of the first child entry with this key; nullopt when there is none or it has no '='.
    std::optional<std::string_view> valueOf(std::string_view key) const;
    // Every child entry with this key, in file order.
    std::vector<const Node*> all(std::string_view key) const;
    std::vector<Node*> all(std::string_view key);

    // The line written last of this node and the lines under it: the one whose line end is the end.
    const Node& lastLine() const;
    Node& lastLine();
    // Appends this line (unless it is the root) and the lines under it as they are written to a file.
    void appendTo(std::string& out) const;
    // The lines of this node as they are written to a file.
    std::string serialize() const;

private:
    friend class LineClassifier;

    std::string raw_;
    std::string decoded_; // only for lines that were not valid UTF-8
    std::vector<Node> children_;
    std::uint32_t keyStart_ = 0;
    std::uint32_t keyLength_ = 0;
    std::uint32_t valueStart_ = 0;
    int lineNumber_ = 0;
    std::int16_t level_ = -1;
    Kind kind_ = Kind::Root;
    Ending ending_ = Ending::Lf;
    bool hasValue_ = false;
};

} // namespace stellwerk::cs2config
