#pragma once

#include "station/DeviceDescription.h"

#include <QDateTime>
#include <QString>
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

// A device on the bus (the station, a Gleisbox, an MS2, a Link S88): what it is and its gauges.
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

private:
    cs2::DeviceIdentity identity_;
    std::optional<station::DeviceSummary> summary_;
    bool described_ = false;
    std::vector<StatusChannel> channels_;
};

} // namespace stellwerk::model
