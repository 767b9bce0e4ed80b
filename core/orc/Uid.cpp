#include "orc/Uid.h"

#include <array>

namespace stellwerk::orc {
namespace {

constexpr std::array<LegacyRange, 6> Ranges{{
    {LegacyKind::MmLoco, "mm-loco", 0x0000, 0x00FF, false},
    {LegacyKind::Sx1Loco, "sx1-loco", 0x0800, 0x0BFF, true},
    {LegacyKind::Mm2Decoder, "mm2-decoder", 0x3000, 0x33FF, false},
    {LegacyKind::DccAccessory, "dcc-accessory", 0x3800, 0x3FFF, true},
    {LegacyKind::MfxLoco, "mfx-loco", 0x4000, 0x7FFF, true},
    {LegacyKind::DccLoco, "dcc-loco", 0xC000, 0xFFFF, true},
}};

std::uint8_t letter(std::string_view name, std::size_t i) {
    return static_cast<std::uint8_t>(name[i]);
}

} // namespace

std::optional<std::uint16_t> developerWord(std::string_view firstName, std::string_view surname) {
    if (firstName.size() < 2 || surname.size() < 2)
        return std::nullopt;
    const std::uint8_t high = letter(surname, 0) ^ letter(firstName, 1);
    const std::uint8_t low = letter(surname, 1) ^ letter(firstName, 0);
    return std::uint16_t(high << 8 | low);
}

std::optional<std::uint16_t> firstFreeBusId(std::uint16_t wanted,
                                            const std::function<bool(std::uint16_t)>& taken) {
    std::uint16_t candidate = wanted;
    for (std::uint32_t tries = 0; tries < 0x10000; ++tries, ++candidate)
        if (!taken(candidate))
            return candidate;
    return std::nullopt;
}

const LegacyRange& legacyRange(LegacyKind kind) {
    for (const LegacyRange& range : Ranges)
        if (range.kind == kind)
            return range;
    return Ranges.front();
}

std::optional<std::uint16_t> legacyId(LegacyKind kind, unsigned number) {
    const LegacyRange& range = legacyRange(kind);
    if (number == 0 || number > unsigned(range.last - range.base))
        return std::nullopt;
    return std::uint16_t(range.base + number);
}

std::optional<LegacyAddress> legacyAddressOf(std::uint16_t busId) {
    for (const LegacyRange& range : Ranges)
        if (busId > range.base && busId <= range.last)
            return LegacyAddress{&range, unsigned(busId - range.base)};
    return std::nullopt;
}

} // namespace stellwerk::orc
