#pragma once

#include "model/Z21Addresses.h"
#include "phones/PhoneSettings.h"

#include <QObject>
#include <QPointer>
#include <QStringList>
#include <memory>

class QSettings;

namespace stellwerk::model {
class Railway;
}
namespace stellwerk::withrottleserver {
class MdnsAnnouncement;
class WiThrottleServer;
} // namespace stellwerk::withrottleserver
namespace stellwerk::z21server {
class Z21Server;
}

namespace stellwerk::phones {

// The desktop's phone servers (issue 35): the Z21 and WiThrottle servers run as the phone settings say
// (both off by default), restarted when those change, in front of the railway in use, sharing the book of
// Z21 addresses that is read from and written to the program's settings. The WiThrottle server is announced
// over mDNS while it runs, as `stellwerk-cli serve` does.
class PhoneServers final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PhoneServers)

public:
    // `settings` (the program's) must outlive this; the Z21 addresses are read from it here.
    explicit PhoneServers(QSettings& settings, QObject* parent = nullptr);
    ~PhoneServers() override;

    // Starts, restarts or stops the servers as `chosen` says, without storing it (a command line's flags);
    // what could not be started ("Z21 21105: <the system's reason>"; empty: all is well).
    QStringList apply(const PhoneSettings& chosen);
    // apply(), and `chosen` stored in the settings for the next start.
    QStringList change(const PhoneSettings& chosen);
    const PhoneSettings& settings() const { return settings_; }

    // The railway the phones drive (RailwayBinding::railwayChanged; null: none now).
    void setRailway(model::Railway* railway);

    z21server::Z21Server* z21() const { return z21_.get(); }
    withrottleserver::WiThrottleServer* withrottle() const { return withrottle_.get(); }
    bool running() const { return z21_ || withrottle_; }
    // What the mDNS announcement of the WiThrottle server says: announced, or why not (empty: no server).
    QString announcement() const;
    // The phones connected now, by the names the servers know them by ("z21 127.0.0.1:5000").
    QStringList clients() const;

    // The Z21 addresses of the locomotives; saveAddresses() after changing them.
    model::Z21Addresses& addresses() { return addresses_; }
    void saveAddresses();

signals:
    void clientsChanged();
    // The servers were started or stopped (their pointers changed).
    void serversChanged();

private:
    QString startZ21();
    QString startWiThrottle();
    void clientsMayHaveChanged();

    QSettings& store_;
    PhoneSettings settings_;
    model::Z21Addresses addresses_;
    QPointer<model::Railway> railway_;
    std::unique_ptr<z21server::Z21Server> z21_;
    std::unique_ptr<withrottleserver::WiThrottleServer> withrottle_;
    std::unique_ptr<withrottleserver::MdnsAnnouncement> announcement_; // ends before the server
};

} // namespace stellwerk::phones
