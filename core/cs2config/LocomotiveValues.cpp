#include "cs2config/LocomotiveValues.h"

#include "cs2config/Text.h"

#include <algorithm>

namespace stellwerk::cs2config::loco {

namespace {

int hexDigit(char c) {
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

// The characters a CS3 writes as "#xx" (seen in its files: space and '/'), plus the ones that would
// break the line format or the escaping itself.
bool needsCs3Escape(unsigned char c) {
    return c < 0x20 || c == ' ' || c == '#' || c == '/' || c == '=' || c == 0x7f;
}

// The bytes of a run of "#xx" escapes starting at text[i]; `i` moves past the run.
std::string escapedRun(std::string_view text, std::size_t& i) {
    std::string bytes;
    while (i + 2 < text.size() && text[i] == '#' && hexDigit(text[i + 1]) >= 0 &&
           hexDigit(text[i + 2]) >= 0) {
        bytes += static_cast<char>(hexDigit(text[i + 1]) * 16 + hexDigit(text[i + 2]));
        i += 3;
    }
    return bytes;
}

} // namespace

std::string cs3Unescape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const std::string run = escapedRun(text, i);
        if (run.empty()) {
            out += text[i++];
            continue;
        }
        // A CS3 escapes ASCII ("#20", "#2F"); escaped bytes that form UTF-8 are taken as UTF-8, any
        // other byte above 0x7F as its Latin-1 character, so that the text is always valid UTF-8.
        out += isValidUtf8(run) ? run : latin1ToUtf8(run);
    }
    return out;
}

std::string cs3Escape(std::string_view text) {
    static constexpr char digits[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (!needsCs3Escape(byte)) {
            out += c;
            continue;
        }
        out += '#';
        out += digits[byte >> 4];
        out += digits[byte & 0x0f];
    }
    return out;
}

std::string readText(const Node* line, TextCoding coding) {
    if (!line || !line->hasValue())
        return {};
    return coding == TextCoding::Cs3Escaped ? cs3Unescape(line->value()) : std::string(line->value());
}

ReadValue<TravelDirection> readDirection(const Node* line) {
    const ReadValue<std::int64_t> raw = readNumber<std::int64_t>(line, 0);
    if (raw.problem == ValueProblem::Missing)
        return {TravelDirection::Forward, ValueProblem::Missing};
    if (raw.problem != ValueProblem::None)
        return {TravelDirection::Unknown, raw.problem};
    if (raw.value == 0 || raw.value == 1)
        return {raw.value == 0 ? TravelDirection::Forward : TravelDirection::Backward, ValueProblem::None};
    return {TravelDirection::Unknown, ValueProblem::OutOfRange};
}

std::string keyLabel(int level, std::string_view key) {
    std::string label(static_cast<std::size_t>(std::max(level, 0)), '.');
    label += key;
    return label;
}

std::string keyLabel(const Node& line) {
    return keyLabel(line.level(), line.key());
}

std::string describe(std::string_view name, int line) {
    const std::string where = "line " + std::to_string(line);
    return name.empty() ? where : quoteForMessage(name) + " (" + where + ")";
}

std::string nameOf(std::string_view name, int line) {
    return name.empty() ? "at line " + std::to_string(line) : quoteForMessage(name);
}

void Findings::note(Kind kind, std::string subject, std::string message, std::string action, int line) {
    const auto [number, first] = messages_.see(message);
    if (!first) {
        ++findings_[number].count;
        return;
    }
    findings_.push_back({kind, std::move(subject), std::move(message), std::move(action), line, 1});
}

void Findings::report(Diagnostics& diagnostics, bool skipKeys) const {
    for (const Finding& finding : findings_) {
        if (skipKeys && finding.kind != Kind::Other)
            continue;
        std::string message = finding.message;
        if (finding.count > 1)
            message += " (" + std::to_string(finding.count) + " times, first here)";
        diagnostics.warning(finding.line, std::move(message), finding.action);
    }
}

std::vector<std::string> Findings::subjects(Kind kind) const {
    std::vector<std::string> keys;
    for (const Finding& finding : findings_)
        if (finding.kind == kind)
            keys.push_back(finding.subject);
    return keys;
}

RecordLines::RecordLines(const Node& record, const Keys& keys, Diagnostics& diagnostics, Findings& findings) {
    for (const Node& child : record.children()) {
        if (!child.isEntry())
            continue;
        const std::string_view key = child.key();
        const auto value = std::find(keys.values.begin(), keys.values.end(), key);
        if (value != keys.values.end()) {
            const auto index = static_cast<std::size_t>(value - keys.values.begin());
            if (!lines_[index])
                lines_[index] = &child;
            else
                diagnostics.warning(child.lineNumber(),
                                    "'" + keyLabel(child) + "' appears twice in a " +
                                        std::string(keys.recordName) + " (lines " +
                                        std::to_string(lines_[index]->lineNumber()) + " and " +
                                        std::to_string(child.lineNumber()) + ")",
                                    "the first one is used; both kept");
            continue;
        }
        if (std::find(keys.blocks.begin(), keys.blocks.end(), key) != keys.blocks.end())
            continue;
        const std::string label = keyLabel(child);
        findings.note(Findings::Kind::UnknownKey, label,
                      "unknown key '" + label + "' in a " + std::string(keys.recordName), "kept unchanged",
                      child.lineNumber());
    }
}

void ValueReader::reportNumber(const Node& line, ValueProblem problem, std::int64_t fallback) {
    const std::string label = "'" + keyLabel(line) + "' ";
    const std::string what = problem == ValueProblem::NotANumber
                                 ? label + "is not a number: " + quoteForMessage(line.value())
                                 : label + "is out of range: " + quoteForMessage(trimmed(line.value()));
    diagnostics_.warning(line.lineNumber(), what, "kept unchanged; read as " + std::to_string(fallback));
}

} // namespace stellwerk::cs2config::loco
