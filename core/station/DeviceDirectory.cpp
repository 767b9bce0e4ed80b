#include "station/DeviceDirectory.h"

namespace stellwerk::station {

bool DeviceDirectory::record(const cs2::DeviceIdentity& identity) {
    const auto [it, added] = byUid_.try_emplace(identity.uid, devices_.size());
    if (added)
        devices_.push_back(DeviceDescription{identity, std::nullopt, {}, {}});
    else
        devices_[it->second].identity = identity;
    return added;
}

void DeviceDirectory::describe(const DeviceDescription& description) {
    record(description.identity);
    DeviceDescription& stored = devices_[byUid_.at(description.identity.uid)];
    stored.summary = description.summary;
    stored.readings = description.readings;
    stored.configs = description.configs;
}

const DeviceDescription* DeviceDirectory::find(std::uint32_t uid) const {
    const auto it = byUid_.find(uid);
    return it == byUid_.end() ? nullptr : &devices_[it->second];
}

} // namespace stellwerk::station
