#include "model/Device.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace stellwerk::model {
namespace {

double labelValue(const std::string& label) {
    double value = 0;
    std::from_chars(label.data(), label.data() + label.size(), value);
    return value;
}

} // namespace

StatusChannel::StatusChannel(station::ReadingChannel description) : description_(std::move(description)) {}

double StatusChannel::minimum() const {
    return labelValue(description_.startLabel);
}

double StatusChannel::maximum() const {
    return labelValue(description_.endLabel);
}

std::array<StatusChannel::Zone, 4> StatusChannel::zones() const {
    std::array<Zone, 4> zones;
    for (std::size_t i = 0; i < zones.size(); ++i) {
        // One byte per colour: red, green, blue and grey, two bits each from the top.
        const std::uint8_t colour = description_.colours[i];
        Zone& zone = zones[i];
        zone.end = description_.scaled(description_.rangeEnds[i]);
        zone.red = (colour >> 6) & 3;
        zone.green = (colour >> 4) & 3;
        zone.blue = (colour >> 2) & 3;
        if (zone.red == 0 && zone.green == 0 && zone.blue == 0)
            zone.red = zone.green = zone.blue = colour & 3;
    }
    return zones;
}

std::optional<double> StatusChannel::value() const {
    if (!raw_)
        return std::nullopt;
    return description_.scaled(*raw_);
}

QString StatusChannel::text() const {
    const auto v = value();
    if (!v)
        return QStringLiteral("–");
    return QStringLiteral("%1 %2").arg(QString::number(*v, 'f', decimals()), unit()).trimmed();
}

bool StatusChannel::confirm(std::uint16_t raw, const QDateTime& now) {
    updated_ = now;
    const bool changed = raw_ != raw || stale_;
    raw_ = raw;
    stale_ = false;
    return changed;
}

bool StatusChannel::markStale() {
    if (stale_)
        return false;
    stale_ = true;
    return true;
}

Device::Device(const cs2::DeviceIdentity& identity) : identity_(identity) {}

Device::Device(const station::DeviceDescription& description)
    : identity_(description.identity), summary_(description.summary),
      described_(description.summary.has_value()) {
    for (const station::ReadingChannel& reading : description.readings)
        channels_.emplace_back(reading);
    for (const station::ConfigChannel& config : description.configs)
        if (config.kind != station::ConfigChannel::Kind::Unknown)
            settings_.emplace_back(config);
}

QString Device::typeName() const {
    const auto name = cs2::deviceTypeName(identity_.deviceType);
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

QString Device::name() const {
    if (summary_ && !summary_->name.empty())
        return QString::fromStdString(summary_->name);
    return typeName();
}

QString Device::article() const {
    return summary_ ? QString::fromStdString(summary_->article) : QString();
}

QString Device::version() const {
    return QStringLiteral("%1.%2").arg(identity_.versionMajor).arg(identity_.versionMinor);
}

StatusChannel* Device::channel(std::uint8_t number) {
    const auto it = std::ranges::find(channels_, number, &StatusChannel::channel);
    return it == channels_.end() ? nullptr : &*it;
}

const StatusChannel* Device::channel(std::uint8_t number) const {
    return const_cast<Device*>(this)->channel(number);
}

DeviceSetting* Device::setting(std::uint8_t number) {
    const auto it = std::ranges::find(settings_, number, &DeviceSetting::channel);
    return it == settings_.end() ? nullptr : &*it;
}

const DeviceSetting* Device::setting(std::uint8_t number) const {
    return const_cast<Device*>(this)->setting(number);
}

DeviceSetting::DeviceSetting(station::ConfigChannel description)
    : description_(std::move(description)), value_(isList() ? description_.current : description_.value) {}

QStringList DeviceSetting::options() const {
    QStringList list;
    for (const std::string& option : description_.options)
        list << QString::fromStdString(option);
    return list;
}

std::uint16_t DeviceSetting::minimum() const {
    return isList() ? 0 : description_.minimum;
}

std::uint16_t DeviceSetting::maximum() const {
    if (isList())
        return std::uint16_t(description_.options.empty() ? 0 : description_.options.size() - 1);
    return std::max(description_.minimum, description_.maximum);
}

double DeviceSetting::scaled(std::uint16_t raw) const {
    const double start = labelValue(description_.startLabel);
    const double end = labelValue(description_.endLabel);
    if (maximum() == minimum() || (start == 0 && end == 0))
        return raw;
    return start + (double(raw) - minimum()) * (end - start) / (maximum() - minimum());
}

std::uint16_t DeviceSetting::rawFor(double scaledValue) const {
    const double start = labelValue(description_.startLabel);
    const double end = labelValue(description_.endLabel);
    double raw = scaledValue;
    if (maximum() != minimum() && end != start)
        raw = minimum() + (scaledValue - start) * (maximum() - minimum()) / (end - start);
    return std::uint16_t(std::clamp(std::lround(raw), long(minimum()), long(maximum())));
}

int DeviceSetting::decimals() const {
    const std::string& label = description_.startLabel;
    const auto dot = label.find('.');
    return dot == std::string::npos ? 0 : int(label.size() - dot - 1);
}

bool DeviceSetting::confirm(std::uint16_t value) {
    if (value == value_)
        return false;
    value_ = value;
    return true;
}

} // namespace stellwerk::model
