#pragma once

#include "cs2/Header.h"
#include "transport/FrameAssembler.h"
#include "transport/TransportSettings.h"

#include <QHostAddress>
#include <QObject>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

class QTcpServer;
class QTcpSocket;
class QUdpSocket;

namespace stellwerk::transport {
class CanBusTransport;
}

namespace stellwerk::sim {

class SimulatedBus;
class SimulatedStation;

// Where the simulated station listens and answers, as a CS2 does: UDP in on 15731 and out to 15730,
// TCP on 15731, and optionally a real CAN interface.
struct StationServerSettings {
    QHostAddress listenAddress{QHostAddress::AnyIPv4};
    bool udp = true;
    std::uint16_t udpPort = transport::StationPort;     // 0 = any free port
    QHostAddress udpReplyHost{QHostAddress::Broadcast}; // where UDP frames go
    std::uint16_t udpReplyPort = transport::ListenPort;
    bool tcp = true;
    std::uint16_t tcpPort = transport::StationPort; // 0 = any free port
    std::optional<transport::CanBusSettings> canBus;
    // Tell each new TCP client the track power as it is now (the CS2 protocol has no query for it).
    bool announcePowerToNewClients = false;
};

// What the server has seen since it started listening.
struct StationServerCounters {
    std::uint64_t framesIn = 0;           // frames given to the station, from any listener
    std::uint64_t framesOut = 0;          // frames the station (and the other peers of its bus) emitted
    std::uint64_t malformedDatagrams = 0; // UDP datagrams that were not n x 13 bytes (dropped)
    std::uint64_t malformedFrames = 0;    // frames with a DLC above 8 (dropped)
    std::uint64_t tcpConnections = 0;     // TCP clients accepted
};

// The network side of the simulated CS2: every frame the station emits reaches every TCP client, the UDP
// reply address and the CAN interface. A frame received from one listener goes to the station and, as
// the CS2's gateway puts it on its CAN bus, to every other listener too (never back to its sender).
// When the station shares a SimulatedBus with other devices (MS1 handhelds), the listeners are that bus's
// outside: they see every frame any of its peers sends, and what they send reaches every peer.
class StationServer : public QObject {
    Q_OBJECT

public:
    StationServer(SimulatedStation& station, StationServerSettings settings, QObject* parent = nullptr);
    // The station is one peer of `bus` (attached by the caller); the server listens for the whole bus.
    StationServer(SimulatedStation& station, SimulatedBus& bus, StationServerSettings settings,
                  QObject* parent = nullptr);
    ~StationServer() override;

    // Opens the configured listeners; false (with errorString()) when a port cannot be bound.
    bool listen();
    QString errorString() const { return error_; }

    // The ports actually bound (useful with port 0); 0 when that listener is off.
    std::uint16_t udpPort() const;
    std::uint16_t tcpPort() const;
    int tcpClientCount() const { return int(clients_.size()); }
    const StationServerCounters& counters() const { return counters_; }
    // "udp 0.0.0.0:15731 -> 255.255.255.255:15730", "tcp 0.0.0.0:15731", "can socketcan/can0".
    QStringList listeners() const;

    // Stalls like a frozen station (a hung screen, a Wi-Fi stall): it stops reading and answering without
    // closing anything. What arrives meanwhile is kept in order, also from a client that goes away (its
    // bytes were in the station's socket), new TCP clients wait in the backlog, and what the station emits
    // waits too. wake() sends what waited and then reads everything at once.
    void stall();
    void wake();
    bool isStalled() const { return stalled_; }

signals:
    void tcpClientsChanged(int count);
    void problem(const QString& message);

private:
    // Where a frame came from, so that it is not sent back there.
    struct Origin {
        enum class Kind { Udp, Tcp, Can } kind;
        const QTcpSocket* socket = nullptr;
    };

    bool listenUdp();
    bool listenTcp();
    void openCanBus();
    void readDatagrams();
    void acceptClients();
    void readClient(QTcpSocket* socket);
    void dropClient(QTcpSocket* socket);
    void received(const std::vector<can::CanFrame>& frames, Origin origin);
    void arrived(std::vector<can::CanFrame> frames, Origin origin);
    void broadcast(std::span<const can::CanFrame> frames, const std::optional<Origin>& except);
    void sendUdp(std::span<const can::CanFrame> frames);

    SimulatedStation& station_;
    SimulatedBus* bus_ = nullptr;
    StationServerSettings settings_;
    QUdpSocket* udp_ = nullptr;
    QTcpServer* tcp_ = nullptr;
    transport::CanBusTransport* canBus_ = nullptr;
    std::map<QTcpSocket*, transport::FrameAssembler> clients_;
    StationServerCounters counters_;
    QString error_;
    bool stalled_ = false;
    std::vector<std::pair<std::vector<can::CanFrame>, Origin>> heldIn_;
    std::vector<can::CanFrame> heldOut_;
};

} // namespace stellwerk::sim
