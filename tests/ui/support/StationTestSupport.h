#pragma once

// Helpers for the widget tests that need a station: a simulated CS2 behind a server on a free loopback
// port, a port nobody listens on, and waiting for a connection's state on the event loop.

#include "connection/StationConnection.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"

#include <QEventLoop>
#include <QTcpServer>
#include <QTimer>
#include <memory>

namespace stellwerk::ui::test {

// The start-up lists devices for half a second, then downloads and asks; generous for a loaded machine.
inline constexpr int ReadyMs = 10000;

// Runs the event loop until the connection reaches `state` (a real loop: the start-up's many round trips
// would crawl under QTest::qWaitFor's sleeps).
inline bool waitForState(const connection::StationConnection& station,
                         connection::StationConnection::State state, int timeoutMs = ReadyMs) {
    if (station.state() == state)
        return true;
    QEventLoop loop;
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    QObject::connect(&station, &connection::StationConnection::stateChanged, &loop,
                     [&loop, state](connection::StationConnection::State reached) {
                         if (reached == state)
                             loop.quit();
                     });
    loop.exec();
    return station.state() == state;
}

// A loopback TCP port that was free a moment ago and that nobody listens on now.
inline std::uint16_t closedTcpPort() {
    QTcpServer server;
    server.listen(QHostAddress::LocalHost, 0);
    return server.serverPort();
}

// The demo layout's simulated CS2, listening for TCP on a free loopback port until stop().
class TestStation {
public:
    TestStation() : station_(sim::StationLayout::demo()) {}
    explicit TestStation(sim::SimulatedStation::Options options)
        : station_(sim::StationLayout::demo(), options) {}

    // Listens on `port` (0: a free one; a station "back" after a stop takes its old port again).
    bool start(std::uint16_t port = 0) {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress(QHostAddress::LocalHost);
        settings.udp = false;
        settings.tcpPort = port;
        server_ = std::make_unique<sim::StationServer>(station_, settings);
        return server_->listen();
    }
    void stop() { server_.reset(); }
    // Stops reading and answering without closing (a frozen station), and reads everything at once again.
    void stall() { server_->stall(); }
    void wake() { server_->wake(); }
    bool stalled() const { return server_ && server_->isStalled(); }
    QString url() const { return QStringLiteral("tcp://127.0.0.1:%1").arg(server_->tcpPort()); }
    std::uint16_t port() const { return server_->tcpPort(); }
    // The simulated CS2 itself, to make things happen on the layout (an S88 contact, ...).
    sim::SimulatedStation& station() { return station_; }

private:
    sim::SimulatedStation station_;
    std::unique_ptr<sim::StationServer> server_;
};

} // namespace stellwerk::ui::test
