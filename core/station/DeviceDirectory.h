#pragma once

#include "station/DeviceDescription.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace stellwerk::station {

// Every device that answered a ping, in the order they first answered, with what their status data
// said once read.
class DeviceDirectory {
public:
    // Returns true when the device is new.
    bool record(const cs2::DeviceIdentity& identity);
    void describe(const DeviceDescription& description);

    const DeviceDescription* find(std::uint32_t uid) const;
    const std::vector<DeviceDescription>& devices() const { return devices_; }
    std::size_t size() const { return devices_.size(); }

private:
    std::vector<DeviceDescription> devices_;
    std::unordered_map<std::uint32_t, std::size_t> byUid_;
};

} // namespace stellwerk::station
