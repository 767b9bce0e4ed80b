#pragma once

#include "cs2/Messages.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace stellwerk::station {

// Status-data index 0 (document 6.2): what a device is and how many channels it describes.
struct DeviceSummary {
    std::uint8_t readingCount = 0;
    std::uint8_t configCount = 0;
    std::uint32_t serial = 0;
    std::string article;  // "60113": printable ASCII only, whatever bytes the device sent
    std::string name;     // "Gleisbox"
    std::string nickname; // what may follow the name (empty for most devices)
};

// One measurement channel (status-data index 1..R): how to read it (system 0x0B channel) and show it.
struct ReadingChannel {
    std::uint8_t index = 0;
    std::uint8_t channel = 0; // the channel for system 0x0B; need not equal the index
    std::int8_t power = 0;    // 10^power
    std::array<std::uint8_t, 4> colours{};
    std::uint16_t zero = 0;
    std::array<std::uint16_t, 4> rangeEnds{};
    std::string name; // "TRACK", "VOLT", "TEMP" or a plain label
    std::string startLabel;
    std::string endLabel;
    std::string unit;

    // start + (raw - zero) * (end - start) / (rangeEnd4 - zero), with start/end read from the labels.
    double scaled(std::uint16_t raw) const;
    // Decimal places the labels use ("0.00" -> 2): how to print a scaled value.
    int decimals() const;
};

// One configuration channel (status-data index R+1..R+C): a list of options or a number.
struct ConfigChannel {
    enum class Kind : std::uint8_t { List = 1, Number = 2, Unknown = 0 };

    std::uint8_t index = 0;
    std::uint8_t channel = 0;
    Kind kind = Kind::Unknown;
    std::string title;
    // List
    std::uint8_t current = 0;
    std::vector<std::string> options;
    // Number
    std::uint16_t minimum = 0;
    std::uint16_t maximum = 0;
    std::uint16_t value = 0;
    std::string startLabel;
    std::string endLabel;
    std::string unit;
};

// A device on the bus: what its ping said and, once read, its status-data description.
struct DeviceDescription {
    cs2::DeviceIdentity identity;
    std::optional<DeviceSummary> summary;
    std::vector<ReadingChannel> readings;
    std::vector<ConfigChannel> configs;
};

// Parsers for the reassembled bytes of one status-data index. nullopt when the block is too short.
std::optional<DeviceSummary> parseDeviceSummary(std::span<const std::uint8_t> bytes);
std::optional<ReadingChannel> parseReadingChannel(std::uint8_t index, std::span<const std::uint8_t> bytes);
std::optional<ConfigChannel> parseConfigChannel(std::uint8_t index, std::span<const std::uint8_t> bytes);

} // namespace stellwerk::station
