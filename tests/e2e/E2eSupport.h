#pragma once

// End to end: the app's side (a real transport and a StationSession) talking to the simulated CS2 (a
// SimulatedStation behind its StationServer) over real loopback sockets or Qt's virtualcan bus. Each
// rig picks free ports; each test process has its own virtual CAN bus.

#include "EventLoopWait.h"
#include "can/FrameText.h"
#include "cs2/Header.h"
#include "cs2/Messages.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "station/StateQueries.h"
#include "station/StationSession.h"
#include "transport/Transport.h"
#include "transport/TransportFactory.h"
#include "transport/TransportSettings.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTcpServer>
#include <QTimer>
#include <QUdpSocket>
#include <chrono>
#include <cstdint>
#include <functional>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

namespace stellwerk::cs2 {
// Failed comparisons show frames as the protocol document writes them.
inline void PrintTo(const CanFrame& frame, std::ostream* out) {
    *out << formatDocument(frame);
}
} // namespace stellwerk::cs2

namespace stellwerk::e2e {

using namespace std::chrono_literals;
using station::CommandResult;

// Long enough for a loaded two-core machine; waits end as soon as the condition holds.
inline constexpr int WaitMs = 5000;

// Runs the event loop until the condition holds, each event as it comes (support::runEventsUntil).
inline bool waitFor(const std::function<bool()>& condition, int timeoutMs = WaitMs) {
    return support::runEventsUntil(condition, timeoutMs);
}

// The loco of each decoder protocol in the demo layout, and its first MM accessory.
inline constexpr std::uint32_t MfxLoco = 0x4001; // BR 218 Ost
inline constexpr std::uint32_t Mm2Loco = 0x0018; // V 100 2023
inline constexpr std::uint32_t DccLoco = 0xC003; // DCC address 3
inline constexpr std::uint32_t FirstTurnout = 0x3000;

// How the app reaches the simulated station.
enum class Wire { Tcp, Udp, VirtualCan };

inline std::string wireName(Wire wire) {
    switch (wire) {
    case Wire::Tcp:
        return "Tcp";
    case Wire::Udp:
        return "Udp";
    case Wire::VirtualCan:
        return "VirtualCan";
    }
    return "?";
}

// The speed the station itself says a locomotive has (its answer to a speed query on `session`), -1 without
// one: what the tests assert the station ends with.
inline int stationSpeedOf(station::StationSession& session, std::uint32_t loco) {
    auto answer = std::make_shared<std::optional<CommandResult>>();
    session.request(station::speedQuery(cs2::LocId(loco)),
                    [answer](const CommandResult& result) { *answer = result; });
    if (!waitFor([&] { return answer->has_value(); }) || !answer->value().succeeded())
        return -1;
    const auto* speed = std::get_if<cs2::LocoSpeed>(&answer->value().answer->body);
    return speed && speed->speed ? int(*speed->speed) : -1;
}

inline std::uint16_t freeTcpPort() {
    QTcpServer probe;
    EXPECT_TRUE(probe.listen(QHostAddress::LocalHost, 0));
    return probe.serverPort();
}

inline std::uint16_t freeUdpPort() {
    QUdpSocket probe;
    EXPECT_TRUE(probe.bind(QHostAddress::LocalHost, 0));
    return probe.localPort();
}

// Retries quickly so that reconnection takes milliseconds.
inline transport::ReconnectTiming fastReconnect() {
    return {20ms, 100ms, 1000ms};
}

// The virtual bus of this test process: "can0" of a virtualcan relay on a port nobody else uses.
inline transport::CanBusSettings virtualBus() {
    static const std::uint16_t relayPort = freeTcpPort();
    transport::CanBusSettings settings;
    settings.plugin = QStringLiteral("virtualcan");
    settings.interfaceName = QStringLiteral("tcp://127.0.0.1:%1/can0").arg(relayPort);
    settings.reconnect = fastReconnect();
    return settings;
}

inline cs2::Message command(cs2::MessageBody body) {
    return cs2::Message{0, false, 0, std::move(body)};
}

// A session with a fixed UID and patient acknowledgements (retries stay allowed: they are part of it).
inline station::StationSettings sessionSettings() {
    station::StationSettings settings;
    settings.uid = 0x53574B01;
    settings.commands = {500ms, 3};
    return settings;
}

// The simulated station behind its server on 127.0.0.1, and the app's transport and session.
class Rig {
public:
    explicit Rig(Wire wire, station::StationSettings settings = sessionSettings(),
                 sim::StationLayout layout = sim::StationLayout::demo())
        : station(std::move(layout)), wire_(wire), settings_(settings) {
        if (wire_ == Wire::Udp)
            appUdpPort_ = freeUdpPort();
    }
    ~Rig() {
        session.reset();
        bus.reset();
        transport.reset();
        server.reset();
    }

    // Listens, connects and waits until the station answered a ping.
    bool start() { return startServer() && connectApp(); }

    // Makes the app's transport and session, opens the transport and waits for the station's answer.
    bool connectApp() {
        transport = transport::createTransport(transportSettings());
        session.reset();
        bus = std::make_unique<bus::Bus>(*transport, busreading::BusProfile::centralStation());
        session = std::make_unique<station::StationSession>(*bus, settings_);
        transport->open();
        return waitFor([&] { return transport->state() == transport::Transport::State::Connected; }) &&
               hearStation();
    }

    // (Re)opens the station's listeners on the ports of the last time (free ones the first time).
    bool startServer() {
        server = std::make_unique<sim::StationServer>(station, serverSettings());
        if (!server->listen()) {
            ADD_FAILURE() << server->errorString().toStdString();
            return false;
        }
        stationTcpPort_ = server->tcpPort();
        stationUdpPort_ = server->udpPort();
        return true;
    }
    void stopServer() { server.reset(); }

    // Pings (every 100 ms) until the station's answer arrived.
    bool hearStation() {
        QElapsedTimer sincePing;
        session->ping();
        sincePing.start();
        return waitFor([&] {
            if (sincePing.elapsed() > 100) {
                session->ping();
                sincePing.restart();
            }
            return session->devices().find(station.uid()) != nullptr;
        });
    }

    // Sends a command through the session's CommandTracker and waits for how it ended.
    CommandResult acknowledge(const cs2::Message& message) {
        auto result = std::make_shared<std::optional<CommandResult>>();
        session->request(message, [result](const CommandResult& r) { *result = r; });
        if (!waitFor([&] { return result->has_value(); }))
            session->tracker().cancelAll();
        return result->value_or(CommandResult{});
    }

    // Over TCP, the app connects to this port instead of the station's (a relay in between).
    void connectAppTo(std::uint16_t tcpPort) { appTcpPort_ = tcpPort; }
    // Over UDP, the station sends to this port instead of the app's (a relay in between).
    void stationRepliesTo(std::uint16_t udpPort) { replyUdpPort_ = udpPort; }
    // The station tells each new TCP client its track power (as the embedded station does).
    bool announcePower = false;
    std::uint16_t stationTcpPort() const { return stationTcpPort_; }
    std::uint16_t stationUdpPort() const { return stationUdpPort_; }
    Wire wire() const { return wire_; }
    std::uint16_t appUdpPort() const { return appUdpPort_; }

    sim::SimulatedStation station;
    std::unique_ptr<sim::StationServer> server;
    std::unique_ptr<transport::Transport> transport;
    std::unique_ptr<bus::Bus> bus;
    std::unique_ptr<station::StationSession> session;

private:
    sim::StationServerSettings serverSettings() const {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.udp = wire_ == Wire::Udp;
        settings.udpPort = stationUdpPort_;
        settings.udpReplyHost = QHostAddress::LocalHost;
        settings.udpReplyPort = replyUdpPort_ ? replyUdpPort_ : appUdpPort_;
        settings.announcePowerToNewClients = announcePower;
        settings.tcp = wire_ == Wire::Tcp;
        settings.tcpPort = stationTcpPort_;
        if (wire_ == Wire::VirtualCan)
            settings.canBus = virtualBus();
        return settings;
    }

    transport::TransportSettings transportSettings() const {
        switch (wire_) {
        case Wire::Tcp:
            return transport::TcpSettings{QStringLiteral("127.0.0.1"),
                                          appTcpPort_ ? appTcpPort_ : stationTcpPort_, fastReconnect()};
        case Wire::Udp:
            return transport::UdpSettings{QStringLiteral("127.0.0.1"), stationUdpPort_, appUdpPort_,
                                          QHostAddress(QHostAddress::LocalHost), fastReconnect()};
        case Wire::VirtualCan:
            break;
        }
        return virtualBus();
    }

    Wire wire_;
    station::StationSettings settings_;
    std::uint16_t appUdpPort_ = 0;
    std::uint16_t appTcpPort_ = 0;
    std::uint16_t replyUdpPort_ = 0;
    std::uint16_t stationTcpPort_ = 0;
    std::uint16_t stationUdpPort_ = 0;
};

} // namespace stellwerk::e2e
