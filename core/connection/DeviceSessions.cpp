#include "connection/DeviceSessions.h"

#include "bus/Bus.h"
#include "transport/Transport.h"

namespace stellwerk::connection {

busreading::BusProfile deviceBusProfile(const DeviceSettings& settings, int index,
                                        const busreading::BusProfile& base) {
    busreading::BusProfile profile = base;
    if (settings.orc.on && settings.orc.bus == index && !base.expects(busreading::Protocol::Orc))
        profile = base.expects(busreading::Protocol::Cs2) ? busreading::BusProfile::openRailCan()
                                                          : busreading::BusProfile{busreading::Protocol::Orc};
    for (const RoModuleSettings& module : settings.roModules)
        if (module.bus == index)
            profile.addRoModule(module.profile.ids);
    return profile;
}

DeviceSessions::DeviceSessions(DeviceSettings settings, std::vector<bus::Bus*> buses, QObject* parent)
    : QObject(parent), settings_(std::move(settings)), buses_(std::move(buses)),
      ro_(settings_.roModules.size()), refused_(settings_.roModules.size(), false) {
    for (std::size_t index = 0; index < buses_.size(); ++index)
        connect(&buses_[index]->transport(), &transport::Transport::stateChanged, this,
                [this, index] { transportChanged(int(index)); });
    refuseUnusable();
}

DeviceSessions::~DeviceSessions() = default;

std::vector<romodule::RoModuleSession*> DeviceSessions::roModules() const {
    std::vector<romodule::RoModuleSession*> sessions;
    for (const auto& session : ro_)
        if (session)
            sessions.push_back(session.get());
    return sessions;
}

romodule::RoModuleSession* DeviceSessions::roModule(const QString& name) const {
    const std::string wanted = name.toStdString();
    for (const auto& session : ro_)
        if (session && session->profile().name == wanted)
            return session.get();
    return nullptr;
}

// Modules on a bus that is not open, or that their bus cannot carry, are refused before anything is sent;
// a session made here only to ask it why is never started.
void DeviceSessions::refuseUnusable() {
    const int busCount = int(buses_.size());
    if (settings_.orc.on && settings_.orc.bus >= busCount) {
        orcRefused_ = true;
        refuse(QStringLiteral("OpenRailCAN central: bus %1 is not open (the connection has %2)")
                   .arg(settings_.orc.bus)
                   .arg(busCount));
    }
    for (std::size_t slot = 0; slot < settings_.roModules.size(); ++slot) {
        const RoModuleSettings& module = settings_.roModules[slot];
        const QString name = QString::fromStdString(module.profile.name);
        if (module.bus >= busCount) {
            refused_[slot] = true;
            refuse(QStringLiteral("RO module \"%1\": bus %2 is not open (the connection has %3)")
                       .arg(name)
                       .arg(module.bus)
                       .arg(busCount));
            continue;
        }
        const romodule::RoModuleSession probe(*buses_[std::size_t(module.bus)], module.profile);
        if (const QString why = probe.problem(); !why.isEmpty()) {
            refused_[slot] = true;
            refuse(QStringLiteral("RO module %1").arg(why));
        }
    }
}

void DeviceSessions::transportChanged(int index) {
    const auto state = buses_[std::size_t(index)]->transport().state();
    if (state == transport::Transport::State::Connected)
        build(index);
    else
        tearDown(index);
}

void DeviceSessions::build(int index) {
    bus::Bus& bus = *buses_[std::size_t(index)];
    bool made = false;
    if (settings_.orc.on && !orcRefused_ && settings_.orc.bus == index && !orc_) {
        orc_ = std::make_unique<orccentral::OrcSession>(bus, settings_.orc.session);
        orc_->start();
        made = true;
    }
    for (std::size_t slot = 0; slot < ro_.size(); ++slot) {
        const RoModuleSettings& module = settings_.roModules[slot];
        if (module.bus != index || refused_[slot] || ro_[slot])
            continue;
        romodule::SessionTiming timing = settings_.roTiming;
        timing.pollPeriod = module.pollPeriod;
        ro_[slot] = std::make_unique<romodule::RoModuleSession>(bus, module.profile, timing);
        ro_[slot]->start();
        made = true;
    }
    if (made)
        emit sessionsChanged();
}

void DeviceSessions::tearDown(int index) {
    bool gone = false;
    if (orc_ && settings_.orc.bus == index) {
        orc_.reset();
        gone = true;
    }
    for (std::size_t slot = 0; slot < ro_.size(); ++slot) {
        if (ro_[slot] && settings_.roModules[slot].bus == index) {
            ro_[slot]->stop();
            ro_[slot].reset();
            gone = true;
        }
    }
    if (gone)
        emit sessionsChanged();
}

void DeviceSessions::refuse(const QString& why) {
    refusals_.append(why);
    emit problem(why);
}

} // namespace stellwerk::connection
