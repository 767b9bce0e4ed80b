#pragma once

// The demo layout's simulated CS2 on a free loopback port, with the station itself at hand so that the
// keyboard and settings tests can check what it did; and a connection with its railway bound to it.

#include "RailwayBinding.h"
#include "StationTestSupport.h"
#include "model/Railway.h"

#include <QTest>
#include <memory>

namespace stellwerk::ui::test {

inline constexpr int CommandMs = 5000; // generous for a loaded machine

class DemoStation {
public:
    DemoStation() : station_(sim::StationLayout::demo()) {}

    bool start() {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress(QHostAddress::LocalHost);
        settings.udp = false;
        settings.tcpPort = 0;
        server_ = std::make_unique<sim::StationServer>(station_, settings);
        return server_->listen();
    }
    // The station goes away: commands get no answer.
    void stop() { server_.reset(); }
    QString url() const { return QStringLiteral("tcp://127.0.0.1:%1").arg(server_->tcpPort()); }
    sim::SimulatedStation& station() { return station_; }

private:
    sim::SimulatedStation station_;
    std::unique_ptr<sim::StationServer> server_;
};

// A controller on the station: a connection and the railway of its session.
class Controller {
public:
    bool connect(const QString& url) {
        connection.connectTo(url);
        return waitForState(connection, connection::StationConnection::State::Ready) && railways.railway();
    }
    model::Railway* railway() const { return railways.railway(); }

    connection::StationConnection connection;
    RailwayBinding railways{connection};
};

} // namespace stellwerk::ui::test
