// Several buses in one connection: the station's and a further one (a gateway with modules behind it).
// Frames of the further bus are counted and shown, never read as the station's; a further bus that goes
// away and comes back, or says garbage, leaves the station as it was; an address that cannot be read
// opens nothing.

#include "ConnectionWaits.h"
#include "EmbeddedStationSupport.h"
#include "ModuleBusPeer.h"
#include "connection/StationConnection.h"
#include "cs2/Codec.h"

#include <QEventLoop>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <algorithm>
#include <gtest/gtest.h>

using namespace stellwerk;
using connection::ConnectionBuses;
using connection::StationConnection;
using State = StationConnection::State;

using namespace stellwerk::connection::test;

namespace {

// "System stop" as a CS2 frame: on the further bus it must not stop anything.
can::CanFrame systemStop() {
    return cs2::encode(cs2::Message{0, false, 0x0300, cs2::SystemStop{0}});
}

// What the connection showed of bus `index`, as the monitor receives it.
struct BusLog {
    BusLog(StationConnection& connection, int index) {
        QObject::connect(&connection.buses(), &ConnectionBuses::busFramesSeen, &context,
                         [this, index](int bus, const std::vector<can::CanFrame>& frames, bool outgoing) {
                             if (bus == index && !outgoing)
                                 received.insert(received.end(), frames.begin(), frames.end());
                         });
    }
    std::vector<can::CanFrame> received;
    QObject context;
};

// The station and one further bus, both up.
struct TwoBuses {
    TwoBuses() : connection(support::withEmbeddedStation()) {}
    bool start() {
        if (!modules.listen())
            return false;
        connection.connectTo(QString(), {modules.url()});
        return ready(connection) &&
               waitUntil([&] { return connection.buses().isBusConnected(1); }, ReadyMs) &&
               waitUntil([&] { return modules.hasClient(); }, ReadyMs);
    }
    support::ModuleBusPeer modules;
    StationConnection connection;
};

TEST(StationConnectionBuses, HoldsTheStationsBusAndTheFurtherOnesInOrder) {
    TwoBuses rig;
    QSignalSpy changed(&rig.connection.buses(), &ConnectionBuses::busesChanged);
    ASSERT_TRUE(rig.start()) << rig.connection.lastProblem().toStdString();
    EXPECT_EQ(changed.count(), 1);
    const std::vector<connection::BusInfo> buses = rig.connection.buses().list();
    ASSERT_EQ(buses.size(), 2u);
    EXPECT_TRUE(buses[0].station);
    EXPECT_TRUE(buses[0].profile.expects(busreading::Protocol::Cs2));
    EXPECT_FALSE(buses[1].station);
    EXPECT_EQ(buses[1].place, QStringLiteral("127.0.0.1:%1").arg(rig.modules.port()));
    EXPECT_FALSE(buses[1].profile.expects(busreading::Protocol::Cs2)) << "no CS2 is expected on a module bus";
    EXPECT_EQ(rig.connection.furtherBuses(), QStringList{rig.modules.url()});

    rig.connection.disconnectFromStation();
    EXPECT_EQ(changed.count(), 2);
    EXPECT_TRUE(rig.connection.buses().list().empty());
    EXPECT_FALSE(rig.connection.buses().isBusConnected(1));
}

// A frame that looks like "system stop" on the module bus is foreign there: counted and shown on bus 1,
// never on the station's bus, and the session never reads it.
TEST(StationConnectionBuses, FurtherBusFramesAreShownAndCountedButNeverReachTheStation) {
    TwoBuses rig;
    ASSERT_TRUE(rig.start());
    BusLog further(rig.connection, 1);
    BusLog station(rig.connection, 0);
    QSignalSpy stationFrames(&rig.connection.buses(), &ConnectionBuses::stationFramesSeen);
    std::vector<station::PowerChange> powers;
    QObject::connect(rig.connection.session(), &station::StationSession::updated, &further.context,
                     [&](const station::StationUpdates& u) {
                         powers.insert(powers.end(), u.power.begin(), u.power.end());
                     });
    const std::uint64_t cs2Before = rig.connection.buses().busFrames(0, busreading::Protocol::Cs2);

    rig.modules.send({systemStop(), systemStop()});
    ASSERT_TRUE(waitUntil([&] { return further.received.size() == 2; }, 3000));
    QTest::qWait(200);
    EXPECT_EQ(further.received, (std::vector{systemStop(), systemStop()}));
    EXPECT_EQ(rig.connection.buses().busFrames(1, busreading::Protocol::Foreign), 2u);
    EXPECT_EQ(rig.connection.buses().busFrames(1, busreading::Protocol::Cs2), 0u);
    EXPECT_EQ(std::count(station.received.begin(), station.received.end(), systemStop()), 0);
    for (const QList<QVariant>& seen : stationFrames)
        for (const can::CanFrame& frame : seen.at(0).value<std::vector<can::CanFrame>>())
            EXPECT_NE(frame, systemStop()) << "the station's bus showed a module frame";
    EXPECT_TRUE(powers.empty()) << "a module frame was read as the station's power";
    EXPECT_GE(rig.connection.buses().busFrames(0, busreading::Protocol::Cs2), cs2Before);
    EXPECT_EQ(rig.connection.state(), State::Ready);
    EXPECT_TRUE(rig.modules.written.isEmpty())
        << "nothing speaks to the modules yet: nothing is written there";
}

TEST(StationConnectionBuses, AFurtherBusThatCannotBeReadFailsTheConnectionAndOpensNothing) {
    StationConnection connection{support::withEmbeddedStation()};
    QSignalSpy changed(&connection.buses(), &ConnectionBuses::busesChanged);
    connection.connectTo(QString(),
                         {QStringLiteral("can://socketcan/can1"), QStringLiteral("http://modules")});
    EXPECT_EQ(connection.state(), State::Failed);
    EXPECT_TRUE(connection.failureReason().startsWith(QStringLiteral("further bus \"http://modules\": ")))
        << connection.failureReason().toStdString();
    EXPECT_EQ(connection.embeddedPort(), 0) << "the simulated station was not left running";
    EXPECT_TRUE(connection.buses().list().empty());
    EXPECT_EQ(connection.session(), nullptr);
    EXPECT_EQ(changed.count(), 0);
}

// The gateway with the modules is unplugged and plugged in again after 1 s or 20 s: the station stays
// ready all along, the loss is reported naming the bus, and its frames come again once it is back.
class FurtherBusGoneFor : public ::testing::TestWithParam<int> {};

TEST_P(FurtherBusGoneFor, TheStationStaysReadyAndTheBusComesBack) {
    const int outageMs = GetParam();
    TwoBuses rig;
    ASSERT_TRUE(rig.start());
    QSignalSpy states(&rig.connection, &StationConnection::stateChanged);
    QSignalSpy problems(&rig.connection, &StationConnection::problem);
    QSignalSpy busesChanged(&rig.connection.buses(), &ConnectionBuses::busesChanged);
    BusLog further(rig.connection, 1);

    rig.modules.stop();
    ASSERT_TRUE(waitUntil([&] { return !rig.connection.buses().isBusConnected(1); }, 5000));
    const QString port = QString::number(rig.modules.port());
    ASSERT_TRUE(waitUntil([&] { return !problems.isEmpty(); }, 5000));
    EXPECT_TRUE(problems.at(0).at(0).toString().contains(port))
        << problems.at(0).at(0).toString().toStdString();
    QTest::qWait(outageMs);
    EXPECT_EQ(rig.connection.state(), State::Ready);
    EXPECT_FALSE(rig.connection.session()->liveness().isStationSilent());

    ASSERT_TRUE(rig.modules.listen());
    ASSERT_TRUE(waitUntil([&] { return rig.connection.buses().isBusConnected(1) && rig.modules.hasClient(); },
                          ReconnectMs));
    rig.modules.send({systemStop()});
    ASSERT_TRUE(waitUntil([&] { return further.received.size() == 1; }, 3000));
    EXPECT_EQ(states.count(), 0) << "the station's state never changed";
    EXPECT_EQ(busesChanged.count(), 0) << "the same bus, away and back: the list never changed";
    EXPECT_EQ(rig.connection.buses().list().size(), 2u);
    EXPECT_TRUE(rig.modules.written.isEmpty());
}

INSTANTIATE_TEST_SUITE_P(BackAfter, FurtherBusGoneFor, ::testing::Values(1000, 20000),
                         [](const auto& info) { return std::to_string(info.param / 1000) + "s"; });

// A gateway that sends a malformed frame (DLC 15) and then a good one: the bad one is left out, the good
// one is counted, the station is not disturbed.
TEST(StationConnectionBuses, GarbageOnAFurtherBusLeavesTheStationAlone) {
    TwoBuses rig;
    ASSERT_TRUE(rig.start());
    QSignalSpy states(&rig.connection, &StationConnection::stateChanged);
    BusLog further(rig.connection, 1);
    QByteArray garbage(13, char(0xEE));
    garbage[4] = char(15);
    rig.modules.sendBytes(garbage + transport::encodeFrames(std::vector{systemStop()}));
    ASSERT_TRUE(waitUntil([&] { return further.received.size() == 1; }, 3000));
    EXPECT_EQ(further.received.front(), systemStop());
    EXPECT_EQ(rig.connection.buses().busFrames(1, busreading::Protocol::Foreign), 1u);
    QTest::qWait(300);
    EXPECT_EQ(states.count(), 0);
    EXPECT_EQ(rig.connection.state(), State::Ready);
}

} // namespace
