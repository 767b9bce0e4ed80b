#include "connection/ConnectionDevices.h"

#include "connection/StationLink.h"

namespace stellwerk::connection {

ConnectionDevices::ConnectionDevices(DeviceSettings settings, std::optional<DeviceSettings> localStation,
                                     QObject* parent)
    : QObject(parent), settings_(std::move(settings)), localStation_(std::move(localStation)) {}

ConnectionDevices::~ConnectionDevices() = default;

orccentral::OrcSession* ConnectionDevices::orcSession() const {
    return link_ && link_->devices ? link_->devices->orc() : nullptr;
}

std::vector<romodule::RoModuleSession*> ConnectionDevices::roModules() const {
    return link_ && link_->devices ? link_->devices->roModules() : std::vector<romodule::RoModuleSession*>{};
}

romodule::RoModuleSession* ConnectionDevices::roModule(const QString& name) const {
    return link_ && link_->devices ? link_->devices->roModule(name) : nullptr;
}

QStringList ConnectionDevices::refusals() const {
    return link_ && link_->devices ? link_->devices->refusals() : QStringList{};
}

bool ConnectionDevices::choose(bool localStation) {
    onLocalStation_ = localStation;
    const bool own = localStation && localStation_.has_value();
    active_ = own ? *localStation_ : settings_;
    return own;
}

void ConnectionDevices::open(StationLink& link) {
    std::vector<bus::Bus*> buses;
    for (const auto& bus : link.buses)
        buses.push_back(bus.get());
    link.devices = std::make_unique<DeviceSessions>(active_, std::move(buses));
    link_ = &link;
    connect(link.devices.get(), &DeviceSessions::sessionsChanged, this, &ConnectionDevices::devicesChanged);
    connect(link.devices.get(), &DeviceSessions::problem, this, &ConnectionDevices::problem);
    for (const QString& refusal : link.devices->refusals())
        emit problem(refusal);
    emit devicesChanged();
}

void ConnectionDevices::release() {
    if (!link_)
        return;
    link_->detach(this); // closing the transports tears the sessions down: no word of it from here
    link_ = nullptr;
    emit devicesChanged();
}

} // namespace stellwerk::connection
