// Issue 32: a station that stalls instead of disconnecting (a frozen Central Station screen, a Wi-Fi stall,
// a loose cable) stops reading without closing, then reads everything at once when it wakes, and so
// carries out the copies of a command the app had already given up on. The real stellwerk-sim is stopped
// (SIGSTOP) for 1 s and for 20 s while the app, as the GUI holds it (StationConnection and Railway, the
// default timings), gives speed commands; then it goes on (SIGCONT). Asserted: what the station ends with,
// asked of the station itself, and what the app shows.

#include "E2eSupport.h"
#include "SimProgram.h"
#include "connection/StationConnection.h"
#include "model/Railway.h"
#include "station/StateQueries.h"
#include "transport/CanBusTransport.h"
#include "transport/TransportAddress.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>
#include <iostream>
#include <tuple>

namespace stellwerk::e2e {
namespace {

using connection::StationConnection;
using model::Railway;

// The real program on free loopback ports; over virtualcan it joins the bus this test process holds.
class StalledStationRig {
public:
    explicit StalledStationRig(Wire wire) : wire_(wire) {}

    bool start() {
        QStringList arguments = support::Quiet;
        if (wire_ == Wire::Udp) {
            appUdpPort_ = freeUdpPort();
            arguments << QStringLiteral("--udp-reply-port") << QString::number(appUdpPort_);
        }
        if (wire_ == Wire::VirtualCan) {
            holder_ = std::make_unique<transport::CanBusTransport>(virtualBus()); // the bus lives here
            holder_->open();
            if (!waitFor([&] { return holder_->state() == transport::Transport::State::Connected; }))
                return false;
            arguments << QStringLiteral("--can")
                      << QStringLiteral("virtualcan:") + virtualBus().interfaceName;
        }
        sim = std::make_unique<support::SimProgram>(arguments);
        const std::uint16_t port =
            sim->port(wire_ == Wire::Tcp ? QStringLiteral("tcp") : QStringLiteral("udp"));
        if (port == 0 || (wire_ == Wire::VirtualCan && !sim->printed(QStringLiteral("listening: can"))))
            return false;
        connectApp(url(port));
        return ready();
    }

    // Ready, the state reported, and no command waiting for its answer.
    bool ready(int timeoutMs = 4 * WaitMs) {
        return waitFor(
            [&] {
                return connection.state() == StationConnection::State::Ready && railway &&
                       railway->isStateReported() && connection.session()->tracker().pendingCount() == 0;
            },
            timeoutMs);
    }

    // Drives and waits until the station confirmed it.
    bool drive(std::uint32_t loco, int speed) {
        railway->setSpeed(loco, speed);
        return waitFor([&] { return shownSpeed(loco) == speed; });
    }

    // The speed the app shows, or -1 while it is not reported.
    int shownSpeed(std::uint32_t loco) const {
        const model::Locomotive* found = railway->locomotive(loco);
        return found && found->isSpeedReported() ? found->speed() : -1;
    }

    // The speed the station itself says the locomotive has (its answer to a speed query), -1 without one.
    int stationSpeed(std::uint32_t loco) { return stationSpeedOf(*connection.session(), loco); }

    std::unique_ptr<support::SimProgram> sim;
    StationConnection connection;
    std::unique_ptr<Railway> railway;

private:
    QString url(std::uint16_t port) const {
        switch (wire_) {
        case Wire::Tcp:
            return QStringLiteral("tcp://127.0.0.1:%1").arg(port);
        case Wire::Udp:
            return QStringLiteral("udp://127.0.0.1:%1?listen=%2").arg(port).arg(appUdpPort_);
        case Wire::VirtualCan:
            break;
        }
        return transport::transportUrl(virtualBus());
    }

    void connectApp(const QString& address) {
        QObject::connect(
            &connection, &StationConnection::sessionStarted, &connection,
            [this](station::StationSession* session) { railway = std::make_unique<Railway>(*session); });
        QObject::connect(&connection, &StationConnection::configurationLoaded, &connection,
                         [this](const station::StartupResult& result) { railway->load(result); });
        connection.connectTo(address);
    }

    Wire wire_;
    std::uint16_t appUdpPort_ = 0;
    std::unique_ptr<transport::CanBusTransport> holder_;
};

class StalledStation : public ::testing::TestWithParam<std::tuple<Wire, int>> {};

// BR 218 stands and gets a speed; V 100 runs and gets a faster one. Both commands are given up while the
// station is stopped; when it goes on it reads them (and their retries) at once. In the end the station
// has what the app last showed as confirmed, and the app shows what the station has.
TEST_P(StalledStation, GivenUpSpeedsAreNotWhatTheStationEndsWith) {
    const auto [wire, stallMs] = GetParam();
    StalledStationRig rig(wire);
    ASSERT_TRUE(rig.start());
    ASSERT_TRUE(rig.drive(MfxLoco, 0));
    ASSERT_TRUE(rig.drive(Mm2Loco, 300));
    QSignalSpy failed(rig.railway.get(), &Railway::locomotiveCommandFailed);
    QSignalSpy corrected(rig.railway.get(), &Railway::stateCorrected);

    ASSERT_TRUE(rig.sim->stall());
    QElapsedTimer stalled;
    stalled.start();
    rig.railway->setSpeed(MfxLoco, 200);
    rig.railway->setSpeed(Mm2Loco, 700);
    ASSERT_TRUE(waitFor([&] { return failed.count() >= 2; })) << "both are given up while it is stopped";
    EXPECT_EQ(rig.railway->locomotive(MfxLoco)->speed(), 0) << "the app never shows the unconfirmed speed";
    EXPECT_EQ(rig.railway->locomotive(Mm2Loco)->speed(), 300);
    QTest::qWait(int(std::max<qint64>(0, stallMs - stalled.elapsed())));
    ASSERT_TRUE(rig.sim->wake());

    ASSERT_TRUE(rig.ready(stallMs + 6 * WaitMs)) << "the station is heard and read again";
    ASSERT_TRUE(
        waitFor([&] { return rig.shownSpeed(MfxLoco) == 0 && rig.shownSpeed(Mm2Loco) == 300; }, 3 * WaitMs));
    QTest::qWait(1500); // a late copy of a given-up command would have arrived by now
    EXPECT_EQ(rig.stationSpeed(MfxLoco), 0) << "the station ends where the app last showed it";
    EXPECT_EQ(rig.stationSpeed(Mm2Loco), 300);
    EXPECT_EQ(rig.shownSpeed(MfxLoco), 0);
    EXPECT_EQ(rig.shownSpeed(Mm2Loco), 300);
    EXPECT_TRUE(rig.railway->isStateReported());
    int late = 0;
    for (const QList<QVariant>& signal : corrected)
        late += signal.at(0).value<model::Correction>().carriedOutLate ? 1 : 0;
    std::cout << "    " << wireName(wire) << ", " << stallMs / 1000 << " s: " << corrected.count()
              << " corrections, " << late << " of them after the station was seen carrying a command out"
              << std::endl;
}

// 1 s: the station wakes soon after the commands were given up. 20 s: well past the give-up, the
// silence (3 s) and, over TCP, the connection reset.
INSTANTIATE_TEST_SUITE_P(Stall, StalledStation,
                         ::testing::Combine(::testing::Values(Wire::Tcp, Wire::Udp, Wire::VirtualCan),
                                            ::testing::Values(1000, 20000)),
                         [](const auto& info) {
                             return wireName(std::get<0>(info.param)) + "For" +
                                    std::to_string(std::get<1>(info.param) / 1000) + "s";
                         });

} // namespace
} // namespace stellwerk::e2e
