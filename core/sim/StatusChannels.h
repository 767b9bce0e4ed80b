#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::sim {

// What a reading channel measures; the station computes it from the track load.
enum class Quantity { MainTrackCurrent, ProgrammingTrackCurrent, Voltage, Temperature };

// One measurement channel as status data configuration describes it (document 6.2): how the raw
// 16-bit value of system status (0x0B) maps to the displayed value.
struct ReadingChannel {
    std::uint8_t channel = 0; // the query channel of system 0x0B and of an overload report
    std::int8_t power = 0;    // power of ten of the value
    std::array<std::uint8_t, 4> colours{};
    std::uint16_t zero = 0;
    std::array<std::uint16_t, 4> rangeEnds{};
    std::string name, startLabel, endLabel, unit;
    Quantity quantity = Quantity::MainTrackCurrent;

    // The raw value that displays as `value` (in the unit), clamped to 0..0xFFFF.
    std::uint16_t rawFor(double value) const;
};

// A configuration channel with a drop-down list (type 1).
struct ListChannel {
    std::uint8_t channel = 0;
    std::string title;
    std::vector<std::string> options;
    std::uint8_t current = 0;
};

// A configuration channel with a slider (type 2).
struct NumberChannel {
    std::uint8_t channel = 0;
    std::string title, startLabel, endLabel, unit;
    std::uint16_t minimum = 0, maximum = 0, current = 0;
};

// Index 0 of status data configuration: who the device is.
struct DeviceDescription {
    std::uint32_t serial = 0;
    std::string article; // at most 8 bytes on the wire
    std::string name;
};

// A device's status data: its description, reading channels (indices 1..R) and configuration
// channels (R+1..), the bytes of each index as the device sends them, and configuration writes.
class StatusChannels {
public:
    // A Central Station 2: main and programming track current, voltage and temperature, a list
    // channel (power supply) and a slider (current limit, channel 6, which sets the overload limit).
    static StatusChannels centralStation(std::uint32_t serial);
    // A Gleisbox 60113 with the channel figures of a real one (field notes).
    static StatusChannels gleisbox(std::uint32_t serial);

    // The bytes of one index (before the frames' zero padding); nullopt for an index the device
    // does not have.
    std::optional<std::vector<std::uint8_t>> indexBytes(std::uint8_t index) const;
    // The raw reading of a channel at this main-track load; nullopt for no such reading channel.
    std::optional<std::uint16_t> reading(std::uint8_t channel, double mainTrackAmpere) const;
    // The current setting of a configuration channel, or nullopt.
    std::optional<std::uint16_t> setting(std::uint8_t channel) const;
    // Sets a configuration channel; false when there is no such channel or the value is out of range.
    bool configure(std::uint8_t channel, std::uint16_t value);

    // The main-track current above which the device reports an overload, in milliampere.
    int currentLimitMa() const;
    // The channel an overload on the main track is reported under.
    std::uint8_t mainTrackChannel() const;

    const DeviceDescription& description() const { return description_; }
    const std::vector<ReadingChannel>& readings() const { return readings_; }

private:
    DeviceDescription description_;
    std::vector<ReadingChannel> readings_;
    std::optional<ListChannel> list_;
    std::optional<NumberChannel> limit_;
    int fixedLimitMa_ = 0;
};

} // namespace stellwerk::sim
