#include "connection/HandheldConnection.h"

#include "bus/Bus.h"
#include "station/DeviceDescription.h"
#include "transport/Transport.h"

#include <algorithm>

namespace stellwerk::connection {
namespace {

// The device type a Central Station's GUI answers a ping with (CS2 document 6.1); it is an M-CAN master.
constexpr std::uint16_t CentralStationGui = 0xFFFF;

} // namespace

HandheldConnection::HandheldConnection(bus::Bus& bus, const HandheldSettings& settings, QObject* parent)
    : QObject(parent), role_(settings.role) {
    transport::Transport& wire = bus.transport();
    master_ = std::make_unique<mcanhandhelds::HandheldMaster>(
        [&wire](const std::vector<can::CanFrame>& frames) { wire.sendBatch(frames); }, settings.master, this);
    master_->setBook(settings.book);
    bus.subscribe(busreading::Protocol::Mcan, master_.get(),
                  [this](const std::vector<can::CanFrame>& frames) { master_->receive(frames); });
    applyRole();
}

HandheldConnection::~HandheldConnection() = default;

void HandheldConnection::devicesListed(const std::vector<station::DeviceDescription>& devices) {
    devicesKnown_ = true;
    centralStation_ =
        std::any_of(devices.begin(), devices.end(), [](const station::DeviceDescription& device) {
            return device.identity.deviceType == CentralStationGui;
        });
    applyRole();
}

void HandheldConnection::setRole(HandheldRole role, const std::vector<station::DeviceDescription>& devices) {
    role_ = role;
    if (!devices.empty())
        devicesListed(devices);
    else
        applyRole();
}

// Automatic answers only once the devices are known and no Central Station is among them.
void HandheldConnection::applyRole() {
    switch (role_) {
    case HandheldRole::Watch:
        master_->standDown(mcanhandhelds::Watching::Asked);
        return;
    case HandheldRole::Master:
        master_->setActive(true);
        return;
    case HandheldRole::Automatic:
        break;
    }
    if (centralStation_)
        master_->standDown(mcanhandhelds::Watching::CentralStation);
    else if (devicesKnown_)
        master_->setActive(true);
    else
        master_->standDown(mcanhandhelds::Watching::UntilDevicesKnown);
}

} // namespace stellwerk::connection
