#include "orccentral/DeviceRegistry.h"

#include "orc/Uid.h"

namespace stellwerk::orccentral {

DeviceRegistry::DeviceRegistry(std::uint16_t centralBusId) : central_(centralBusId) {}

OrcDevice* DeviceRegistry::byUid(std::uint32_t uid) {
    for (OrcDevice& device : devices_)
        if (device.uid == uid)
            return &device;
    return nullptr;
}

OrcDevice* DeviceRegistry::byBusId(std::uint16_t busId) {
    for (OrcDevice& device : devices_)
        if (device.busId == busId)
            return &device;
    return nullptr;
}

bool DeviceRegistry::taken(std::uint16_t busId, std::uint32_t uid) const {
    if (busId == central_ || reserved_.count(busId))
        return true;
    for (const OrcDevice& device : devices_)
        if (device.busId == busId && device.uid != uid)
            return true;
    return false;
}

std::optional<std::uint16_t> DeviceRegistry::busIdFor(std::uint32_t uid) const {
    for (const OrcDevice& device : devices_)
        if (device.uid == uid)
            return device.busId;
    return orc::firstFreeBusId(orc::wantedBusId(uid), [&](std::uint16_t id) { return taken(id, uid); });
}

OrcDevice& DeviceRegistry::enter(std::uint32_t uid, std::uint16_t busId, std::uint8_t type) {
    OrcDevice* device = byUid(uid);
    if (!device) {
        devices_.push_back(OrcDevice{});
        device = &devices_.back();
        device->uid = uid;
    }
    device->busId = busId;
    device->type = type;
    return *device;
}

} // namespace stellwerk::orccentral
