#pragma once

#include "model/RailwayFollower.h"
#include "withrottle/ClientMessages.h"
#include "withrottle/ServerLines.h"
#include "withrottleserver/WiThrottleClient.h"
#include "withrottleserver/WiThrottleRailway.h"

#include <QElapsedTimer>
#include <QHostAddress>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>
#include <chrono>
#include <list>
#include <memory>

class QTcpServer;
class QTimer;
class QTcpSocket;

namespace stellwerk::model {
class Railway;
class Z21Addresses;
} // namespace stellwerk::model

namespace stellwerk::withrottleserver {

using namespace std::chrono_literals;

// Where and how the server listens.
struct WiThrottleServerOptions {
    QHostAddress address = QHostAddress::Any;
    quint16 port = 12090;                      // JMRI's port; 0: any free one
    std::chrono::milliseconds heartbeat = 10s; // announced as *<seconds> (at least 1)
    std::chrono::milliseconds grace = 5s;      // silence past heartbeat + grace: the client is gone
    int linesPerSecond = 100;                  // per client; more are dropped and counted
    std::size_t maxLineLength = withrottle::LineSplitter::DefaultMaxLineLength;
    std::string serverName = "Stellwerk";
    QList<QHostAddress> allowedClients; // only these may connect; empty: every address
};

// What the server counted since it started.
struct WiThrottleCounters {
    std::uint64_t connections = 0;
    std::uint64_t lines = 0;
    std::uint64_t unknownLines = 0; // ignored, as the protocol says
    std::uint64_t overlongLines = 0;
    std::uint64_t limited = 0;    // lines dropped by the flood limit
    std::uint64_t refused = 0;    // commands refused while the station is not heard
    std::uint64_t notAllowed = 0; // connections closed at once: not from an allowed client
};

// One thing that happened to a client, for the log and the command line's serve.
struct WiThrottleEvent {
    enum class Kind : std::uint8_t {
        Joined,
        Named,
        Acquired,
        Released,
        StealNeeded,
        TakenOver,
        Refused,
        Flooding,
        Quit,
        Left,
        TimedOut,
        Dropped
    };
    Kind kind = Kind::Joined;
    QString client;
    QString detail;
};

// A WiThrottle server in front of the railway (issue 35): Engine Driver and WiThrottle connect over TCP,
// are sent the roster, turnouts, routes and track power, and drive the railway's locomotives through its
// throttle port, one throttle per client (a loco another throttle drives must be stolen; the one that loses
// it is told). Changes from anywhere reach the clients holding the loco (speed, direction, functions) and
// every client (power, turnouts). A client silent past its heartbeat or gone from the network has its
// locomotives stopped. While the station is not heard the power is shown unknown and commands are refused
// with a message, never queued.
class WiThrottleServer final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(WiThrottleServer)

public:
    WiThrottleServer(model::Z21Addresses& addresses, WiThrottleServerOptions options = {},
                     QObject* parent = nullptr);
    ~WiThrottleServer() override;

    // Listens; false (errorString() says why) when the address or port cannot be had.
    bool listen();
    QString errorString() const;
    quint16 port() const;
    // The railway the clients drive (null: none now; the power is shown unknown, commands refused).
    void setRailway(model::Railway* railway);
    // Stops every locomotive a client drives and closes every connection (the server is ending).
    void stopAll();
    // Closes the client's connection (its WiThrottleClient::name()) and stops the locomotives it drives:
    // the operator let it go. False for a client not connected now.
    bool dropClient(const QString& client);

    const WiThrottleCounters& counters() const { return counters_; }
    // The clients connected now.
    std::size_t clientCount() const;
    const std::list<WiThrottleClient>& clients() const { return clients_; }

signals:
    void event(const stellwerk::withrottleserver::WiThrottleEvent& event);

private:
    // WiThrottleServer.cpp: connections, the clients' lives and what they are sent.
    void accept();
    bool allows(const QHostAddress& peer) const;
    void read(WiThrottleClient& client);
    void greet(WiThrottleClient& client);
    void dropSilent();
    void goAway(WiThrottleClient& client, WiThrottleEvent::Kind why);
    WiThrottleClient* find(const QString& name);
    WiThrottleClient* find(const QTcpSocket* socket);
    void send(WiThrottleClient& client, const withrottle::ServerLine& line);
    void sendAll(const withrottle::ServerLine& line);
    void locosChanged(const QList<quint32>& locIds);
    void tellLoco(WiThrottleClient& client, char throttle, ThrottleLoco& loco);
    void turnoutsChanged(const QList<qint64>& keyboardNumbers);
    void routesChanged();
    void powerChanged();
    void takenOver(quint32 locId, const QString& from, const QString& to);
    model::RailwayFollower::Changes railwayChanges();
    void tell(WiThrottleEvent::Kind kind, const WiThrottleClient& client, const QString& detail = {});
    qint64 now() const { return clock_.elapsed(); }
    int heartbeatSeconds() const;

    // WiThrottleServerRequests.cpp: one line of a client.
    void handle(WiThrottleClient& client, const withrottle::ClientMessage& message);
    void acquire(WiThrottleClient& client, const withrottle::AcquireLoco& request);
    void hold(WiThrottleClient& client, const withrottle::AcquireLoco& request, std::uint32_t locId);
    void release(WiThrottleClient& client, const withrottle::ReleaseLoco& request);
    void act(WiThrottleClient& client, const withrottle::ThrottleAction& request);
    void actOn(WiThrottleClient& client, char throttle, ThrottleLoco& loco,
               const withrottle::LocoAction& action);
    void pressFunction(WiThrottleClient& client, std::uint32_t locId, const withrottle::FunctionKey& key);
    void setPower(WiThrottleClient& client, bool on);
    void switchTurnout(WiThrottleClient& client, const withrottle::SwitchTurnout& request);
    void setRoute(WiThrottleClient& client, const withrottle::SetRoute& request);
    bool canDrive(WiThrottleClient& client);
    void quit(WiThrottleClient& client);

    model::Z21Addresses& addresses_;
    WiThrottleServerOptions options_;
    QTcpServer* listener_;
    QTimer* heartbeatTimer_;
    QElapsedTimer clock_;
    std::list<WiThrottleClient> clients_; // stable addresses: sockets' slots hold a client's place
    WiThrottleCounters counters_;
    QPointer<model::Railway> railway_;
    std::unique_ptr<WiThrottleRailway> wiRailway_;
    model::RailwayFollower follower_; // last: it lets go of the railway before the rest is gone
};

} // namespace stellwerk::withrottleserver
