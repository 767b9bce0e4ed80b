#include "model/Accessory.h"

#include <algorithm>
#include <utility>

namespace stellwerk::model {
namespace {

constexpr int OutputsPerAddress = 2;

} // namespace

Accessory Accessory::fromFile(const cs2config::Accessory& record) {
    Accessory a;
    a.id_ = record.id;
    a.name_ = QString::fromStdString(record.name);
    a.type_ = QString::fromStdString(record.type);
    a.typeKey_ = record.type;
    a.addresses_ = std::max(1, record.addressCount());
    a.dcc_ = record.protocol == "dcc";
    a.switchTimeMs_ = record.switchTimeMs;
    a.position_ = int(record.position);
    return a;
}

int Accessory::positionCount() const {
    const auto* info = typeInfo();
    return info ? info->positions : OutputsPerAddress;
}

bool Accessory::acceptsPosition(int position) const {
    const auto* info = typeInfo();
    if (info)
        return info->acceptsPosition(position);
    return position >= 0 && position < OutputsPerAddress * addresses_;
}

bool Accessory::confirmPosition(int position) {
    const bool newlyReported = !std::exchange(positionReported_, true);
    if (position == position_)
        return newlyReported;
    position_ = position;
    return true;
}

std::optional<cs2::LocId> Accessory::address(int n) const {
    if (n < 0 || n >= addresses_ || id_ < 1)
        return std::nullopt;
    const auto protocol = dcc_ ? cs2::Protocol::DccAccessory : cs2::Protocol::Mm2Accessory;
    return cs2::LocId::fromAddress(protocol, std::uint32_t(id_ + n));
}

std::optional<AccessoryOutput> Accessory::outputFor(int position) const {
    if (!acceptsPosition(position))
        return std::nullopt;
    const int addressIndex = addresses_ > 1 ? position / OutputsPerAddress : 0;
    const int output = addresses_ > 1 ? position % OutputsPerAddress : position;
    const auto wire = address(addressIndex);
    if (!wire)
        return std::nullopt;
    return AccessoryOutput{*wire, std::uint8_t(output)};
}

int Accessory::positionOf(int addressIndex, std::uint8_t output) const {
    return addresses_ > 1 ? addressIndex * OutputsPerAddress + output : output;
}

} // namespace stellwerk::model
