#include "sim/StatusChannels.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace stellwerk::sim {
namespace {

// Colours of the document's example: green, yellow, yellow, red (RGB and grey, 2 bits each).
constexpr std::array<std::uint8_t, 4> trafficLight{0x31, 0xF2, 0xF2, 0xC3};
constexpr double nominalVolt = 19.0;
constexpr double voltDropPerAmpere = 0.4;
constexpr double idleCelsius = 30.0;
constexpr double celsiusPerAmpere = 8.0;

double number(const std::string& label) {
    double value = 0;
    std::from_chars(label.data(), label.data() + label.size(), value);
    return value; // labels are plain decimals; from_chars ignores the process locale
}

// Appends big-endian integers and NUL-terminated strings.
class Bytes {
public:
    Bytes& u8(std::uint8_t v) { return bytes_.push_back(v), *this; }
    Bytes& u16(std::uint16_t v) { return u8(std::uint8_t(v >> 8)).u8(std::uint8_t(v)); }
    Bytes& u32(std::uint32_t v) { return u16(std::uint16_t(v >> 16)).u16(std::uint16_t(v)); }
    Bytes& text(const std::string& s) {
        bytes_.insert(bytes_.end(), s.begin(), s.end());
        return u8(0);
    }
    Bytes& fixed(const std::string& s, std::size_t size) {
        for (std::size_t i = 0; i < size; ++i)
            u8(i < s.size() ? std::uint8_t(s[i]) : 0);
        return *this;
    }
    std::vector<std::uint8_t> take() { return std::move(bytes_); }

private:
    std::vector<std::uint8_t> bytes_;
};

std::vector<std::uint8_t> describe(const ReadingChannel& c) {
    Bytes b;
    b.u8(c.channel).u8(std::uint8_t(c.power));
    for (std::uint8_t colour : c.colours)
        b.u8(colour);
    b.u16(c.zero);
    for (std::uint16_t end : c.rangeEnds)
        b.u16(end);
    return b.text(c.name).text(c.startLabel).text(c.endLabel).text(c.unit).take();
}

std::vector<std::uint8_t> describe(const ListChannel& c) {
    Bytes b;
    b.u8(c.channel).u8(1).u8(std::uint8_t(c.options.size())).u8(c.current).u32(0).text(c.title);
    for (const std::string& option : c.options)
        b.text(option);
    return b.take();
}

std::vector<std::uint8_t> describe(const NumberChannel& c) {
    Bytes b;
    b.u8(c.channel).u8(2).u16(c.minimum).u16(c.maximum).u16(c.current);
    return b.text(c.title).text(c.startLabel).text(c.endLabel).text(c.unit).take();
}

double measure(Quantity quantity, double ampere) {
    switch (quantity) {
    case Quantity::MainTrackCurrent:
        return ampere;
    case Quantity::ProgrammingTrackCurrent:
        return 0.0;
    case Quantity::Voltage:
        return nominalVolt - voltDropPerAmpere * ampere;
    case Quantity::Temperature:
        return idleCelsius + celsiusPerAmpere * ampere;
    }
    return 0.0;
}

ReadingChannel makeReading(std::uint8_t channel, std::int8_t power, std::uint16_t zero,
                           std::array<std::uint16_t, 4> ends, std::array<std::string, 4> texts,
                           Quantity quantity) {
    return {channel, power, trafficLight, zero, ends, texts[0], texts[1], texts[2], texts[3], quantity};
}

} // namespace

std::uint16_t ReadingChannel::rawFor(double value) const {
    const double start = number(startLabel), end = number(endLabel);
    if (end == start)
        return zero;
    const double raw = zero + (value - start) * (rangeEnds[3] - zero) / (end - start);
    return std::uint16_t(std::clamp(std::lround(raw), 0L, 0xFFFFL));
}

StatusChannels StatusChannels::centralStation(std::uint32_t serial) {
    StatusChannels s;
    s.description_ = {serial, "60215", "Central Station 2"};
    s.readings_ = {
        makeReading(1, -3, 0, {3000, 3500, 4000, 4500}, {"HGL", "0.000", "4.500", "A"},
                    Quantity::MainTrackCurrent),
        makeReading(2, -3, 0, {700, 800, 900, 1000}, {"PGL", "0.000", "1.000", "A"},
                    Quantity::ProgrammingTrackCurrent),
        makeReading(3, -1, 0, {150, 170, 210, 250}, {"VOLT", "0.0", "25.0", "V"}, Quantity::Voltage),
        makeReading(4, 0, 0, {60, 70, 80, 90}, {"TEMP", "0", "90", "C"}, Quantity::Temperature),
    };
    s.list_ = ListChannel{5,
                          "Betrieb mit Stromversorgung",
                          {"Trafo 60 VA 60052", "Schaltnetzteil 60061", "Schaltnetzteil 60101"},
                          2};
    s.limit_ = NumberChannel{6, "Variable Strombegrenzung", "0.500", "4.500", "A", 500, 4500, 4000};
    return s;
}

StatusChannels StatusChannels::gleisbox(std::uint32_t serial) {
    StatusChannels s;
    s.description_ = {serial, "60113", "Gleisbox"};
    s.readings_ = {
        makeReading(1, -3, 0x000F, {0x0670, 0x06C2, 0x0767, 0x080C}, {"TRACK", "0.00", "2.50", "A"},
                    Quantity::MainTrackCurrent),
        makeReading(3, -2, 0, {0x039D, 0x04B2, 0x0A1E, 0x0C49}, {"VOLT", "10.00", "27.00", "Volt"},
                    Quantity::Voltage),
        makeReading(4, -1, 0, {0x006B, 0x00A4, 0x00CD, 0x00DB}, {"TEMP", "0.0", "80.0", "C"},
                    Quantity::Temperature),
    };
    s.fixedLimitMa_ = 1900;
    return s;
}

std::optional<std::vector<std::uint8_t>> StatusChannels::indexBytes(std::uint8_t index) const {
    const std::size_t configs = (list_ ? 1 : 0) + (limit_ ? 1 : 0);
    if (index == 0) {
        Bytes b;
        b.u8(std::uint8_t(readings_.size())).u8(std::uint8_t(configs)).u16(0).u32(description_.serial);
        return b.fixed(description_.article, 8).text(description_.name).take();
    }
    if (index <= readings_.size())
        return describe(readings_[index - 1u]);
    const std::size_t config = index - readings_.size() - 1;
    if (config == 0 && list_)
        return describe(*list_);
    if (config == (list_ ? 1u : 0u) && limit_)
        return describe(*limit_);
    return std::nullopt;
}

std::optional<std::uint16_t> StatusChannels::reading(std::uint8_t channel, double mainTrackAmpere) const {
    for (const ReadingChannel& c : readings_)
        if (c.channel == channel)
            return c.rawFor(measure(c.quantity, mainTrackAmpere));
    return std::nullopt;
}

std::optional<std::uint16_t> StatusChannels::setting(std::uint8_t channel) const {
    if (list_ && list_->channel == channel)
        return list_->current;
    if (limit_ && limit_->channel == channel)
        return limit_->current;
    return std::nullopt;
}

bool StatusChannels::configure(std::uint8_t channel, std::uint16_t value) {
    if (list_ && list_->channel == channel && value < list_->options.size()) {
        list_->current = std::uint8_t(value);
        return true;
    }
    if (limit_ && limit_->channel == channel && value >= limit_->minimum && value <= limit_->maximum) {
        limit_->current = value;
        return true;
    }
    return false;
}

int StatusChannels::currentLimitMa() const {
    return limit_ ? limit_->current : fixedLimitMa_;
}

std::uint8_t StatusChannels::mainTrackChannel() const {
    for (const ReadingChannel& c : readings_)
        if (c.quantity == Quantity::MainTrackCurrent)
            return c.channel;
    return 1;
}

} // namespace stellwerk::sim
