#include "can/FrameText.h"

#include <charconv>
#include <optional>
#include <vector>

namespace stellwerk::can {
namespace {

using Tokens = std::vector<std::string_view>;
using Result = Expected<ParsedFrame, std::string>;

Tokens split(std::string_view line) {
    Tokens tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == '\n'))
            ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '\n')
            ++i;
        if (i > start)
            tokens.push_back(line.substr(start, i - start));
    }
    return tokens;
}

bool isHex(std::string_view text) {
    if (text.empty())
        return false;
    for (char c : text)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')))
            return false;
    return true;
}

std::optional<std::uint64_t> hexValue(std::string_view text) {
    if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X'))
        text.remove_prefix(2);
    if (!isHex(text) || text.size() > 16)
        return std::nullopt;
    std::uint64_t value = 0;
    std::from_chars(text.data(), text.data() + text.size(), value, 16);
    return value;
}

std::optional<std::uint8_t> byteValue(std::string_view text) {
    if (text.size() != 2 || !isHex(text))
        return std::nullopt;
    return std::uint8_t(*hexValue(text));
}

// A frame with the identifier written as `text`: up to 3 hex digits make a standard (11-bit) identifier,
// more make an extended (29-bit) one (the candump convention, "123#..." vs "00000123#...").
Expected<CanFrame, std::string> parseId(std::string_view text) {
    const auto value = hexValue(text);
    if (!value)
        return "'" + std::string(text) + "' is not a hexadecimal CAN identifier";
    const std::string_view digits = text.starts_with("0x") || text.starts_with("0X") ? text.substr(2) : text;
    CanFrame frame;
    frame.extended = digits.size() > 3;
    if (!frame.extended && *value > CanFrame::StandardIdMask)
        return "standard identifier " + std::string(text) + " does not fit in 11 bits (7FF at most)";
    if (*value > CanFrame::ExtendedIdMask)
        return "identifier " + std::string(text) + " does not fit in 29 bits";
    frame.id = std::uint32_t(*value);
    return frame;
}

// Bytes are missing after `given` of them. A DLC above 8 is the mistake then, not the bytes: no count
// of bytes would have made such a frame right.
std::string missingBytes(const CanFrame& frame, std::size_t given) {
    if (frame.dlc > 8)
        return "DLC " + std::to_string(frame.dlc) + " is above 8: a CAN frame has at most 8 data bytes (" +
               std::to_string(given) + " given)";
    return "DLC " + std::to_string(frame.dlc) + " announces " + std::to_string(frame.size()) +
           " data bytes, only " + std::to_string(given) + " given";
}

// Fills frame.data from byte tokens, checking them against the DLC.
std::optional<std::string> fillData(CanFrame& frame, const Tokens& tokens, std::size_t first) {
    const std::size_t count = frame.size();
    for (std::size_t i = 0; i < count; ++i) {
        if (first + i >= tokens.size())
            return missingBytes(frame, i);
        auto token = tokens[first + i];
        if (const auto paren = token.find('('); paren != std::string_view::npos && paren > 0)
            token = token.substr(0, paren); // can-monitor shows padding as "7b(00)"
        const auto byte = byteValue(token);
        if (!byte && token.size() == 2)
            return "data byte '" + std::string(tokens[first + i]) + "' is not two hex digits";
        if (!byte)
            return missingBytes(frame, i) + " before '" + std::string(tokens[first + i]) + "'";
        frame.data[i] = *byte;
    }
    if (first + count < tokens.size() && byteValue(tokens[first + count]))
        return "more data bytes than DLC " + std::to_string(frame.dlc) + " announces";
    return std::nullopt;
}

Result parseCandump(const Tokens& tokens, std::size_t at) {
    const auto token = tokens[at];
    const auto hash = token.find('#');
    const auto idText = token.substr(0, hash);
    auto dataText = token.substr(hash + 1);
    if (!dataText.empty() && dataText[0] == '#')
        return std::string("CAN FD frames (##) do not occur on a CS2 bus");
    if (!dataText.empty() && (dataText[0] == 'R' || dataText[0] == 'r'))
        return std::string("remote frames (#R) are not used by the CS2 protocol");
    auto parsed = parseId(idText);
    if (!parsed)
        return parsed.error();
    std::string digits;
    for (char c : dataText)
        if (c != '.')
            digits.push_back(c);
    if (digits.size() % 2 != 0 || (!digits.empty() && !isHex(digits)))
        return "candump data '" + std::string(dataText) + "' is not a sequence of hex bytes";
    if (digits.size() > 16)
        return "candump data has " + std::to_string(digits.size() / 2) + " bytes; a CAN frame has at most 8";
    CanFrame frame = *parsed;
    frame.dlc = std::uint8_t(digits.size() / 2);
    for (std::size_t i = 0; i < frame.dlc; ++i)
        frame.data[i] = *byteValue(std::string_view(digits).substr(2 * i, 2));
    return ParsedFrame{frame, FrameNotation::Candump};
}

Result parseBracketed(const Tokens& tokens, std::size_t dlcAt) {
    if (dlcAt == 0)
        return std::string("a [DLC] needs the identifier before it");
    const auto dlcText = tokens[dlcAt].substr(1, tokens[dlcAt].size() - 2);
    unsigned dlc = 0;
    const auto [end, ec] = std::from_chars(dlcText.data(), dlcText.data() + dlcText.size(), dlc);
    if (ec != std::errc() || end != dlcText.data() + dlcText.size() || dlc > 15)
        return "'" + std::string(tokens[dlcAt]) + "' is not a DLC of 0..15";
    auto parsed = parseId(tokens[dlcAt - 1]);
    if (!parsed)
        return parsed.error();
    CanFrame frame = *parsed;
    frame.dlc = std::uint8_t(dlc);
    if (const auto error = fillData(frame, tokens, dlcAt + 1))
        return *error;
    return ParsedFrame{frame, FrameNotation::Bracketed};
}

Result parseNetwork(std::string_view hex) {
    std::array<std::uint8_t, CanFrame::NetworkSize> bytes{};
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = *byteValue(hex.substr(2 * i, 2));
    const CanFrame frame = CanFrame::fromNetwork(bytes);
    // The network form pads the data to eight bytes: a DLC above 8 cannot be written in it, and
    // bits above the 29-bit identifier do not exist on the bus.
    if (frame.dlc > 8)
        return "the network form's DLC byte (digits 9-10) is " + std::to_string(frame.dlc) +
               "; a CAN frame has at most 8 data bytes";
    if ((frame.id & ~CanFrame::ExtendedIdMask) != 0)
        return "identifier " + std::string(hex.substr(0, 8)) + " does not fit in 29 bits";
    return ParsedFrame{frame, FrameNotation::Network};
}

Result parseDocument(const Tokens& tokens) {
    auto parsed = parseId(tokens[0]);
    if (!parsed)
        return parsed.error();
    if (tokens.size() < 2)
        return "'" + std::string(tokens[0]) + "' needs a DLC after it (document notation: ID DLC BYTES...)";
    unsigned dlc = 0;
    const auto [end, ec] = std::from_chars(tokens[1].data(), tokens[1].data() + tokens[1].size(), dlc);
    if (ec != std::errc() || end != tokens[1].data() + tokens[1].size() || dlc > 15)
        return "'" + std::string(tokens[1]) + "' is not a DLC of 0..15";
    CanFrame frame = *parsed;
    frame.dlc = std::uint8_t(dlc);
    if (const auto error = fillData(frame, tokens, 2))
        return *error;
    return ParsedFrame{frame, FrameNotation::Document};
}

bool isBracketedDlc(std::string_view token) {
    return token.size() >= 3 && token.front() == '[' && token.back() == ']';
}

std::string hexBytes(const CanFrame& frame, const char* separator) {
    std::string out;
    for (std::size_t i = 0; i < frame.size(); ++i) {
        if (i > 0)
            out += separator;
        appendHex(out, frame.data[i], 2);
    }
    return out;
}

} // namespace

Expected<ParsedFrame, std::string> parseFrame(std::string_view line) {
    const Tokens tokens = split(line);
    if (tokens.empty())
        return std::string("empty line");
    for (std::size_t i = 0; i < tokens.size() && i < 3; ++i)
        if (tokens[i].find('#') != std::string_view::npos)
            return parseCandump(tokens, i);
    for (std::size_t i = 0; i < tokens.size(); ++i)
        if (isBracketedDlc(tokens[i]))
            return parseBracketed(tokens, i);
    if (tokens[0].size() == 2 * CanFrame::NetworkSize && isHex(tokens[0]))
        return parseNetwork(tokens[0]);
    if (tokens.size() >= CanFrame::NetworkSize && tokens[0].size() == 2) {
        std::string joined;
        for (std::size_t i = 0; i < CanFrame::NetworkSize; ++i)
            joined += tokens[i];
        if (isHex(joined) && joined.size() == 2 * CanFrame::NetworkSize)
            return parseNetwork(joined);
    }
    return parseDocument(tokens);
}

std::string formatDocument(const CanFrame& frame) {
    std::string out = formatId(frame) + " " + std::to_string(frame.dlc);
    if (frame.size() > 0)
        out += " " + hexBytes(frame, " ");
    return out;
}

std::string formatCandump(const CanFrame& frame) {
    return formatId(frame) + "#" + hexBytes(frame, "");
}

std::string formatNetwork(const CanFrame& frame) {
    std::string out;
    for (const std::uint8_t byte : frame.toNetwork())
        appendHex(out, byte, 2);
    return out;
}

// An identifier too wide for its frame keeps all its digits.
std::string formatId(const CanFrame& frame) {
    std::string out;
    appendHex(out, frame.id, frame.extended ? 8 : 3);
    return out;
}

void appendHex(std::string& out, std::uint64_t value, unsigned digits) {
    static constexpr char Digits[] = "0123456789ABCDEF";
    char buffer[16];
    unsigned count = 0;
    do {
        buffer[count++] = Digits[value & 15];
        value >>= 4;
    } while (value != 0);
    for (unsigned i = count; i < digits; ++i)
        out += '0';
    while (count > 0)
        out += buffer[--count];
}

} // namespace stellwerk::can
