#include "mcanhandhelds/LocoFacts.h"

#include <algorithm>
#include <cmath>

namespace stellwerk::mcanhandhelds {

int railwaySpeed(int handheldSpeed) {
    return int(std::lround(std::clamp(handheldSpeed, 0, 127) * 1000.0 / 127.0));
}

int handheldSpeed(int railwaySpeed) {
    return int(std::lround(std::clamp(railwaySpeed, 0, 1000) * 127.0 / 1000.0));
}

std::uint8_t speedByte(int speed, bool forward) {
    return std::uint8_t(std::clamp(speed, 0, 127) | (forward ? 0 : 0x80));
}

namespace {

// The Latin-1 letters German and its neighbours use, spelt in ASCII.
std::string spelt(char32_t c) {
    switch (c) {
    case U'ä':
        return "ae";
    case U'ö':
        return "oe";
    case U'ü':
        return "ue";
    case U'Ä':
        return "Ae";
    case U'Ö':
        return "Oe";
    case U'Ü':
        return "Ue";
    case U'ß':
        return "ss";
    case U'é':
    case U'è':
        return "e";
    default:
        return c >= 0x20 && c < 0x7F ? std::string(1, char(c)) : std::string("?");
    }
}

// The next code point of UTF-8 text at i (advancing i); a byte that starts no sequence reads as itself.
char32_t nextCodePoint(const std::string& text, std::size_t& i) {
    const auto byte = static_cast<unsigned char>(text[i++]);
    if (byte < 0xC0 || byte >= 0xF8)
        return byte;
    const int more = byte >= 0xF0 ? 3 : byte >= 0xE0 ? 2 : 1;
    char32_t c = byte & (0x3F >> more);
    for (int k = 0; k < more && i < text.size(); ++k, ++i) {
        const auto follow = static_cast<unsigned char>(text[i]);
        if ((follow & 0xC0) != 0x80)
            return U'?';
        c = (c << 6) | (follow & 0x3F);
    }
    return c;
}

} // namespace

std::string handheldName(const std::string& utf8) {
    std::string name;
    for (std::size_t i = 0; i < utf8.size() && name.size() < 16;)
        name += spelt(nextCodePoint(utf8, i));
    return name.substr(0, 16);
}

std::array<char, 16> nameSegments(const std::string& name) {
    std::array<char, 16> segments{};
    const std::string shown = handheldName(name);
    std::copy(shown.begin(), shown.end(), segments.begin());
    return segments;
}

} // namespace stellwerk::mcanhandhelds
