#pragma once

#include "station/DeviceDescription.h"

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::model {

// One measurement of a device as a gauge shows it: its scale from the status data description and
// the value last read (system status 0x0B), scaled into the unit.
class StatusChannel {
public:
    explicit StatusChannel(station::ReadingChannel description);

    std::uint8_t channel() const { return description_.channel; }
    QString name() const { return QString::fromStdString(description_.name); }
    QString unit() const { return QString::fromStdString(description_.unit); }
    int decimals() const { return description_.decimals(); }
    // The scale's ends as the device labels them ("0.00" .. "2.50").
    double minimum() const;
    double maximum() const;
    const station::ReadingChannel& description() const { return description_; }
    // A coloured stretch of the scale (green, yellow, red ...) up to `end`, in the unit; each colour
    // component 0..3 as the description's 2-bit fields give it.
    struct Zone {
        double end = 0;
        int red = 0;
        int green = 0;
        int blue = 0;
    };
    // The description's four range ends and colours, scaled like the value; the first zone starts at
    // minimum().
    std::array<Zone, 4> zones() const;

    std::optional<std::uint16_t> raw() const { return raw_; }
    std::optional<double> value() const;
    // "21.8 Volt"; "–" before the first reading.
    QString text() const;
    const QDateTime& updated() const { return updated_; }
    // True when the last request got no answer: the value shown is old.
    bool stale() const { return stale_; }

    bool confirm(std::uint16_t raw, const QDateTime& now);
    bool markStale();

private:
    station::ReadingChannel description_;
    std::optional<std::uint16_t> raw_;
    QDateTime updated_;
    bool stale_ = false;
};

// One configuration channel of a device (status data R+1..R+C: a list of options or a number with a
// range), and the value the device last reported for it, so that a settings page can show and write it.
class DeviceSetting {
public:
    explicit DeviceSetting(station::ConfigChannel description);

    std::uint8_t channel() const { return description_.channel; }
    bool isList() const { return description_.kind == station::ConfigChannel::Kind::List; }
    bool isNumber() const { return description_.kind == station::ConfigChannel::Kind::Number; }
    QString title() const { return QString::fromStdString(description_.title); }
    QStringList options() const;
    // The raw range of a number channel (a list's: 0 .. options - 1).
    std::uint16_t minimum() const;
    std::uint16_t maximum() const;
    bool accepts(std::uint16_t value) const { return value >= minimum() && value <= maximum(); }
    // A number channel's value in its unit: the labels' range spread over the raw range ("0.500" ..
    // "4.500" A over 500 .. 4500), with the labels' decimals.
    double scaled(std::uint16_t raw) const;
    std::uint16_t rawFor(double scaledValue) const;
    int decimals() const;
    QString unit() const { return QString::fromStdString(description_.unit); }
    const station::ConfigChannel& description() const { return description_; }

    // The list index or raw number the device last reported.
    std::uint16_t value() const { return value_; }
    bool confirm(std::uint16_t value);

private:
    station::ConfigChannel description_;
    std::uint16_t value_ = 0;
};

// How a device answered a configuration write.
enum class SettingResult : std::uint8_t { Accepted, Refused, NoAnswer };

// A device on the bus (the station, a Gleisbox, an MS2, a Link S88): what it is, its gauges and its
// settings.
class Device {
public:
    explicit Device(const cs2::DeviceIdentity& identity);
    explicit Device(const station::DeviceDescription& description);

    std::uint32_t uid() const { return identity_.uid; }
    std::uint16_t deviceType() const { return identity_.deviceType; }
    QString typeName() const;
    QString name() const;    // the status data's name, else the type's name
    QString article() const; // "60113", empty when not described
    QString version() const; // "1.39"
    bool described() const { return described_; }
    const std::vector<StatusChannel>& channels() const { return channels_; }
    StatusChannel* channel(std::uint8_t number);
    const StatusChannel* channel(std::uint8_t number) const;
    const std::vector<DeviceSetting>& settings() const { return settings_; }
    DeviceSetting* setting(std::uint8_t number);
    const DeviceSetting* setting(std::uint8_t number) const;

private:
    cs2::DeviceIdentity identity_;
    std::optional<station::DeviceSummary> summary_;
    bool described_ = false;
    std::vector<StatusChannel> channels_;
    std::vector<DeviceSetting> settings_;
};

} // namespace stellwerk::model
