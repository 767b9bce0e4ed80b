#pragma once

#include "busreading/FrameClassifier.h"
#include "connection/DeviceSettings.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <memory>
#include <vector>

namespace stellwerk::bus {
class Bus;
}

namespace stellwerk::connection {

// What bus `index` is to expect once the device settings are applied to `base` (its profile without
// devices): ORC with the central on it (without M-CAN on the station's bus: their priorities overlap, notes
// O26), and the ids of every RO module wired to it.
busreading::BusProfile deviceBusProfile(const DeviceSettings& settings, int index,
                                        const busreading::BusProfile& base);

// The device sessions of one connection: the OpenRailCAN central and one session per RO module, each on
// the bus the settings name. A session lives while its bus is connected: it is made and started when the
// bus's transport connects, and torn down when the bus goes away (a module that was switched off with it
// has forgotten nothing, but its answers in flight are lost), so that every return starts from a fresh
// read. A module that cannot work where it is wired (an 11-bit module on a UDP/TCP gateway, a bus that is
// not open) is refused once, with the reason, and never made.
class DeviceSessions final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(DeviceSessions)

public:
    DeviceSessions(DeviceSettings settings, std::vector<bus::Bus*> buses, QObject* parent = nullptr);
    ~DeviceSessions() override;

    // The central while its bus is connected and the settings want it, else null.
    orccentral::OrcSession* orc() const { return orc_.get(); }
    // The sessions of the modules whose bus is connected, in the settings' order.
    std::vector<romodule::RoModuleSession*> roModules() const;
    romodule::RoModuleSession* roModule(const QString& name) const;
    // Why modules (or the central) were refused, one sentence each.
    const QStringList& refusals() const { return refusals_; }

signals:
    // Sessions were made or torn down: whoever holds one asks again.
    void sessionsChanged();
    void problem(const QString& message);

private:
    void refuseUnusable();
    void transportChanged(int index);
    void build(int index);
    void tearDown(int index);
    void refuse(const QString& why);

    DeviceSettings settings_;
    std::vector<bus::Bus*> buses_;
    std::unique_ptr<orccentral::OrcSession> orc_;
    std::vector<std::unique_ptr<romodule::RoModuleSession>> ro_; // one slot per module of the settings
    std::vector<bool> refused_;                                  // the same
    bool orcRefused_ = false;
    QStringList refusals_;
};

} // namespace stellwerk::connection
