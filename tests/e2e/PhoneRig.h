#pragma once

// The phones' rig of the e2e tests: the real stellwerk-sim on a loopback TCP port that stays the same when it
// is started again; the app's connection and railway on it as the window holds them (StationConnection and
// RailwayBinding, the default timings), and the Z21 and WiThrottle servers in front of that railway on free
// loopback ports.

#include "E2eSupport.h"
#include "SimProgram.h"
#include "binding/RailwayBinding.h"
#include "connection/StationConnection.h"
#include "model/Railway.h"
#include "model/ThrottlePort.h"
#include "model/Z21Addresses.h"
#include "station/StateQueries.h"
#include "withrottleserver/WiThrottleServer.h"
#include "z21server/Z21Server.h"

#include <memory>
#include <optional>

namespace stellwerk::e2e {

// The demo's V 100 (MM2 24): the locomotive the phones drive.
inline constexpr quint32 PhoneLoco = Mm2Loco;

class PhoneRig {
public:
    PhoneRig() : port_(freeTcpPort()) {
        QObject::connect(&binding, &binding::RailwayBinding::railwayChanged, &binding,
                         [this](model::Railway* railway) {
                             z21.setRailway(railway);
                             withrottle.setRailway(railway);
                         });
    }

    bool start() {
        if (!startStation())
            return false;
        connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(port_));
        return z21.listen() && withrottle.listen() && ready();
    }
    bool startStation() {
        QStringList arguments = support::Quiet;
        arguments[arguments.indexOf(QStringLiteral("--tcp-port")) + 1] = QString::number(port_);
        sim = std::make_unique<support::SimProgram>(arguments);
        return sim->tcpPort() == port_;
    }

    // Ready, the state reported, and no command waiting for its answer.
    bool ready(int timeoutMs = 4 * WaitMs) {
        return waitFor(
            [&] {
                model::Railway* railway = binding.railway();
                return connection.state() == stellwerk::connection::StationConnection::State::Ready &&
                       railway && railway->isStateReported() &&
                       connection.session()->tracker().pendingCount() == 0;
            },
            timeoutMs);
    }

    // The speed the railway shows as confirmed, or -1 while it is not reported.
    int confirmedSpeed() const {
        const auto run =
            binding.railway() ? binding.railway()->throttlePort().confirmed(PhoneLoco) : std::nullopt;
        return run ? run->speed : -1;
    }

    // The speed the station itself says the locomotive has (its answer to a speed query), -1 without one.
    int stationSpeed() { return stationSpeedOf(*connection.session(), PhoneLoco); }

    std::unique_ptr<support::SimProgram> sim;
    stellwerk::connection::StationConnection connection;
    binding::RailwayBinding binding{connection};
    model::Z21Addresses addresses;
    z21server::Z21Server z21{addresses, z21OnLoopback()};
    withrottleserver::WiThrottleServer withrottle{addresses, withrottleOnLoopback()};

private:
    static z21server::Z21ServerOptions z21OnLoopback() {
        z21server::Z21ServerOptions options;
        options.address = QHostAddress::LocalHost;
        options.port = 0; // a free one
        return options;
    }
    static withrottleserver::WiThrottleServerOptions withrottleOnLoopback() {
        withrottleserver::WiThrottleServerOptions options;
        options.address = QHostAddress::LocalHost;
        options.port = 0;
        return options;
    }

    std::uint16_t port_;
};

} // namespace stellwerk::e2e
