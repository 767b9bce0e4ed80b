#pragma once

#include "connection/DeviceSettings.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

namespace stellwerk::orccentral {
class OrcSession;
}
namespace stellwerk::romodule {
class RoModuleSession;
}

namespace stellwerk::connection {

class StationLink;

// The devices' face of a connection, all the devices panel and the device bindings may see: the
// OpenRailCAN central and the RO module sessions while their buses are connected, the devices the
// connection uses, why some were refused, and the device settings kept for later connections. The
// StationConnection owns it (devices()) and opens and closes its sessions with each connection.
class ConnectionDevices final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ConnectionDevices)

public:
    // `localStation`: the devices the local station brings, used instead of `settings` when connected to it
    // (none: it brings none).
    ConnectionDevices(DeviceSettings settings, std::optional<DeviceSettings> localStation,
                      QObject* parent = nullptr);
    ~ConnectionDevices() override;

    // The OpenRailCAN central while its bus is connected and the devices want it, else null.
    orccentral::OrcSession* orcSession() const;
    // The RO module sessions whose bus is connected, in the devices' order; one by name (or null).
    std::vector<romodule::RoModuleSession*> roModules() const;
    romodule::RoModuleSession* roModule(const QString& name) const;
    // Why devices were refused on this connection (an 11-bit module on a UDP/TCP gateway, a bus that is
    // not open), one sentence each; also told as problem().
    QStringList refusals() const;
    // Whether a connection is open: its devices are active().
    bool isOpen() const { return link_ != nullptr; }
    // Whether that connection is to the program's local (simulated) station.
    bool onLocalStation() const { return isOpen() && onLocalStation_; }
    // The devices of the current connection (the local station's own when connected to it).
    const DeviceSettings& active() const { return active_; }
    // The devices for later connections (the current one keeps its own until it connects again).
    const DeviceSettings& settings() const { return settings_; }
    void setSettings(DeviceSettings settings) { settings_ = std::move(settings); }

signals:
    // A connection opened or closed, or sessions were made (their bus connected) or torn down (it went
    // away): whoever holds one asks orcSession() / roModules() again.
    void devicesChanged();
    // Something a person should see (a refusal, a module that does not answer).
    void problem(const QString& message);

private:
    friend class StationConnection;
    // The devices of the next connection: the local station's own when it is to the local station and
    // that brings some (true: their buses come first), else the settings'.
    bool choose(bool localStation);
    // Makes the sessions of active() on the link's buses (kept by the link); refusals are told at once.
    void open(StationLink& link);
    // The connection closed: its sessions go with it.
    void release();

    DeviceSettings settings_;
    std::optional<DeviceSettings> localStation_;
    DeviceSettings active_;
    bool onLocalStation_ = false;
    StationLink* link_ = nullptr;
};

} // namespace stellwerk::connection
