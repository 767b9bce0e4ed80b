#include "ro/Messages.h"

#include <array>

namespace stellwerk::ro {
namespace {

constexpr std::array<std::string_view, 5> WidthNames = {"none", "bit", "byte", "word", "long"};
constexpr std::array<std::string_view, 5> WriteNames = {"ro.write", "ro.write-bit", "ro.write-byte",
                                                        "ro.write-word", "ro.write-long"};
constexpr std::array<std::string_view, 5> ReadNames = {"ro.read", "ro.read-bit", "ro.read-byte",
                                                       "ro.read-word", "ro.read-long"};

} // namespace

std::string_view widthName(Width width) {
    return std::size_t(width) < WidthNames.size() ? WidthNames[std::size_t(width)] : "?";
}

bool widthFromName(std::string_view name, Width& width) {
    for (std::size_t i = 1; i < WidthNames.size(); ++i)
        if (WidthNames[i] == name) {
            width = Width(i);
            return true;
        }
    return false;
}

unsigned byteCount(Width width) {
    switch (width) {
    case Width::None:
        return 0;
    case Width::Bit:
    case Width::Byte:
        return 1;
    case Width::Word:
        return 2;
    case Width::Long:
        return 4;
    }
    return 0;
}

std::uint32_t maxValue(Width width) {
    switch (width) {
    case Width::None:
        return 0;
    case Width::Bit:
        return 1;
    case Width::Byte:
        return 0xFF;
    case Width::Word:
        return 0xFFFF;
    case Width::Long:
        return 0xFFFFFFFF;
    }
    return 0;
}

std::string_view Request::name() const {
    const auto& names = isWrite() ? WriteNames : ReadNames;
    return std::size_t(width) < names.size() ? names[std::size_t(width)] : names[0];
}

std::string_view nameOf(const Answer& answer) {
    return std::visit([](const auto& a) { return a.name; }, answer);
}

} // namespace stellwerk::ro
