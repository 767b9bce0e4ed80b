#pragma once

#include "model/RailwayFollower.h"
#include "z21/Replies.h"
#include "z21/Requests.h"
#include "z21server/Z21Clients.h"
#include "z21server/Z21Railway.h"

#include <QElapsedTimer>
#include <QHostAddress>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>
#include <chrono>
#include <memory>

class QTimer;
class QUdpSocket;

namespace stellwerk::model {
class Railway;
class Z21Addresses;
} // namespace stellwerk::model

namespace stellwerk::z21server {

using namespace std::chrono_literals;

// Where and how the server listens.
struct Z21ServerOptions {
    QHostAddress address = QHostAddress::Any;
    quint16 port = 21105;                    // the Z21's port (spec 1.1); 0: any free one
    std::chrono::milliseconds silence = 60s; // a client silent this long is dropped
    int datagramsPerSecond = 200;            // per client; more are dropped and counted
    std::uint32_t serialNumber = 0x5354454C; // "STEL"
    QList<QHostAddress> allowedClients;      // only these may talk to the server; empty: every address
};

// What the server counted since it started.
struct Z21Counters {
    std::uint64_t datagrams = 0;
    std::uint64_t requests = 0;
    std::uint64_t wrongChecksums = 0; // answered all the same
    std::uint64_t badPackets = 0;     // wrong length, cut short, garbage
    std::uint64_t limited = 0;        // datagrams dropped by the flood limit
    std::uint64_t refused = 0;        // commands refused while the station is not heard
    std::uint64_t unknown = 0;        // answered with "unknown command"
    std::uint64_t notAllowed = 0;     // datagrams ignored: their sender is not an allowed client
};

// One thing that happened to a client, for the log and the command line's serve.
struct Z21Event {
    enum class Kind : std::uint8_t {
        Joined,
        LoggedOff,
        TimedOut,
        Dropped,
        Drove,
        TakenOver,
        Refused,
        Flooding
    };
    Kind kind = Kind::Joined;
    QString client;
    std::uint16_t address = 0; // the loco's Z21 address, where there is one
    QString detail;
};

// A Z21 command station in front of the railway (issue 35): Roco's Z21 app and WLANmaus drive its
// locomotives and switch its turnouts over UDP through the railway's throttle port, as one throttle each
// (last writer wins, the one before told). Every client is known by address and port with its broadcast
// flags and the locomotives it follows; changes from anywhere reach the clients that follow them; a client
// that logs off or falls silent has its locomotives stopped. While the station is not heard, clients are
// told the track power is off and their commands are refused, never queued.
class Z21Server final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(Z21Server)

public:
    Z21Server(model::Z21Addresses& addresses, Z21ServerOptions options = {}, QObject* parent = nullptr);
    ~Z21Server() override;

    // Binds the socket; false (errorString() says why) when the address or port cannot be had.
    bool listen();
    QString errorString() const;
    quint16 port() const;
    // The railway the clients drive (null: none now; every client is told the power is off).
    void setRailway(model::Railway* railway);
    // Stops every locomotive a client drives and forgets the clients (the server is ending).
    void stopAll();
    // Forgets the client (its Z21Client::name()) and stops the locomotives it drives, as when it falls
    // silent: the operator let it go. False for a client the server does not know.
    bool dropClient(const QString& client);

    const Z21Counters& counters() const { return counters_; }
    const Z21Clients& clients() const { return clients_; }

signals:
    void event(const stellwerk::z21server::Z21Event& event);

private:
    // Z21Server.cpp: the socket, the clients' lives and the broadcasts.
    void readDatagrams();
    bool allows(const QHostAddress& from) const;
    void receive(const QByteArray& datagram, const QHostAddress& from, quint16 port);
    void dropSilent();
    void goAway(const Z21Client& client, Z21Event::Kind why);
    void send(const Z21Client& client, const z21::Reply& reply);
    void broadcast(std::uint32_t flags, const z21::Reply& reply);
    void locosChanged(const QList<quint32>& locIds);
    void sendLocoInfo(const Z21Client& client, std::uint16_t address);
    void turnoutsChanged(const QList<qint64>& keyboardNumbers);
    void powerChanged();
    void takenOver(quint32 locId, const QString& from, const QString& to);
    model::RailwayFollower::Changes railwayChanges();
    void tell(Z21Event::Kind kind, const Z21Client& client, std::uint16_t address = 0,
              const QString& detail = {});
    qint64 now() const { return clock_.elapsed(); }

    // Z21ServerRequests.cpp: one request of a client.
    void handle(Z21Client& client, const z21::Request& request);
    void answer(Z21Client& client, const z21::RequestBody& body);
    void onLoco(Z21Client& client, const z21::RequestBody& body);
    void onTurnout(Z21Client& client, const z21::RequestBody& body);
    void onPower(Z21Client& client, const z21::RequestBody& body);
    void drive(Z21Client& client, const z21::SetLocoDrive& request);
    void function(Z21Client& client, const z21::SetLocoFunction& request);
    void emergencyStop(Z21Client& client, std::uint16_t address);
    std::optional<std::uint32_t> drivable(Z21Client& client, std::uint16_t address);
    void refuse(Z21Client& client, std::uint16_t address);
    void unknown(Z21Client& client);

    model::Z21Addresses& addresses_;
    Z21ServerOptions options_;
    QUdpSocket* socket_;
    QTimer* silenceTimer_;
    QElapsedTimer clock_;
    Z21Clients clients_;
    Z21Counters counters_;
    QPointer<model::Railway> railway_;
    std::unique_ptr<Z21Railway> z21Railway_;
    model::RailwayFollower follower_; // last: it lets go of the railway before the rest is gone
};

} // namespace stellwerk::z21server
