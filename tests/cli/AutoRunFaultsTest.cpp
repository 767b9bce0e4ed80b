// Issue 34's faults over real sockets: `stellwerk-cli auto run` drives the demo's trains on the real
// stellwerk-sim while something goes wrong: another program on the bus drives a train, throws a reserved
// turnout or reports an unknown occupant, the station's turnout answers are lost, junk reaches the
// program, the station stalls (SIGSTOP) or is killed and started again. Asserted: what reached the station
// (its speeds, asked on the bus; the commands a neighbour on the bus heard), what the program printed, and
// the simulator's referee: no accident.

#include "../e2e/JunkRelay.h"
#include "AutoRunRig.h"

#include <QRegularExpression>
#include <QTest>
#include <functional>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <memory>
#include <set>

namespace stellwerk::cli {
namespace {

using namespace test;

constexpr std::uint32_t Br218 = 0x4001, Ice = 0x4002, V100 = 0x0018;
const QStringList ThreeTrains{"--place", "mfx:1=1", "--place", "mfx:2=4", "--place", "mm2:24=2"};
const QStringList OneTrain{"--place", "mfx:1=1"};

// The demo's blocks by the contact each holds (device 0).
const std::map<QString, std::uint16_t> DemoContacts{{"Gleis 2", 2}, {"Abstellgleis", 9}, {"Einfahrt West", 7},
                                                    {"Gleis 1", 1}, {"Ausfahrt Ost", 8}, {"Block 1", 3},
                                                    {"Block 2", 4}, {"Block 3", 5},      {"Block 4", 6}};

QString loc(std::uint32_t locId) {
    return QStringLiteral("0x%1").arg(locId, 4, 16, QLatin1Char('0'));
}

// The simulator with the trains placed, on a free HTTP port (the referee) and a TCP port (0: a free one).
class DemoStation {
public:
    explicit DemoStation(const QStringList& trains, std::uint16_t tcpPort = 0, const QStringList& more = {})
        : http_(freePort()), sim_(QStringList{"--listen", "127.0.0.1", "--udp-port", "0", "--udp-reply-host",
                                              "127.0.0.1", "--tcp-port", QString::number(tcpPort),
                                              "--http-port", QString::number(http_), "--tick", "20"} +
                                  more + trains) {}

    std::uint16_t port() { return sim_.tcpPort(); }
    int accidents() { return accidentsOn(http_)["total"].toInt(-1); }
    support::SimProgram& program() { return sim_; }

private:
    std::uint16_t http_;
    support::SimProgram sim_;
};

// Between the program and the station: passes everything on but the station's frames that `eats` takes,
// as a gateway or a wire that loses them would. The station acts on the commands; the program never hears
// their answers.
class FrameEater : public QObject {
public:
    FrameEater(std::uint16_t stationPort, std::function<bool(const cs2::Message&)> eats)
        : stationPort_(stationPort), eats_(std::move(eats)) {
        server_.listen(QHostAddress::LocalHost, 0);
        connect(&server_, &QTcpServer::newConnection, this, &FrameEater::accept);
    }
    std::uint16_t port() const { return server_.serverPort(); }
    int eaten() const { return eaten_; }

private:
    void accept() {
        while (QTcpSocket* app = server_.nextPendingConnection()) {
            auto* station = new QTcpSocket(app);
            auto assembler = std::make_shared<transport::FrameAssembler>();
            station->connectToHost(QHostAddress::LocalHost, stationPort_);
            connect(app, &QTcpSocket::readyRead, station, [app, station] { station->write(app->readAll()); });
            connect(station, &QTcpSocket::readyRead, app,
                    [this, app, station, assembler] { pass(*app, station->readAll(), *assembler); });
            connect(app, &QTcpSocket::disconnected, app, &QObject::deleteLater);
        }
    }
    void pass(QTcpSocket& app, const QByteArray& bytes, transport::FrameAssembler& assembler) {
        std::vector<can::CanFrame> frames, passed;
        assembler.feed(transport::asBytes(bytes), frames);
        for (const can::CanFrame& frame : frames) {
            const cs2::DecodeResult decoded = cs2::decode(frame);
            if (decoded && eats_(*decoded))
                ++eaten_;
            else
                passed.push_back(frame);
        }
        app.write(transport::encodeFrames(passed));
    }

    std::uint16_t stationPort_;
    std::function<bool(const cs2::Message&)> eats_;
    QTcpServer server_;
    int eaten_ = 0;
};

// The station's answers to the commands for turnout 2.
bool turnout2Answer(const cs2::Message& message) {
    const auto* switching = std::get_if<cs2::AccessorySwitch>(&message.body);
    return switching && message.response && switching->article.value() == 0x3001;
}

// The station's reports of contacts 8 (Ausfahrt Ost) and 3 (Block 1): dead contacts.
bool deadContactReport(const cs2::Message& message) {
    const auto* report = std::get_if<cs2::S88Event>(&message.body);
    return report && message.response && report->device == 0 &&
           (report->contact == 8 || report->contact == 3);
}

// The station's speed of every train, asked until all are 0 (true) or the time is up.
bool allStand(BusNeighbour& neighbour, const std::vector<std::uint32_t>& trains, int timeoutMs = 5000) {
    return support::runEventsUntil(
        [&] {
            for (const std::uint32_t train : trains)
                if (neighbour.stationSpeed(train) != 0)
                    return false;
            return true;
        },
        timeoutMs);
}

// Lines of the run, from `from` on, whose text holds `text`.
int linesSaying(AutoRunProcess& run, const QString& text, std::size_t from = 0) {
    int n = 0;
    for (std::size_t i = from; i < run.events().size(); ++i)
        n += run.events()[i]["text"].toString().contains(text);
    return n;
}

// Whether every train of the demo was, after line `from`, told to stop when the station answered again, or
// found lost (no longer where it stood: it is stopped as well).
bool everyTrainStoppedOnReturn(AutoRunProcess& run, std::size_t from) {
    for (const std::uint32_t train : {Br218, Ice, V100}) {
        bool stopped = false;
        for (std::size_t i = from; i < run.events().size() && !stopped; ++i) {
            const QJsonObject& event = run.events()[i];
            stopped =
                event["loc"] == loc(train) &&
                (event["text"].toString().contains("the station answers again") || event["event"] == "lost");
        }
        if (!stopped)
            return false;
    }
    return true;
}

// Another program on the bus drives the running BR 218 (stops it, as a person on a second Central Station
// would): it is manual at once, the automation sends it nothing more, and while the ICE and the V 100 run
// on, neither enters the blocks the BR 218 holds.
TEST(AutoRunFaults, AnotherProgramDrivingATrainMakesItManualAndNothingEntersItsBlocks) {
    ensureApplication();
    DemoStation station(ThreeTrains);
    ASSERT_NE(station.port(), 0) << station.program().output().toStdString();
    BusNeighbour neighbour;
    ASSERT_TRUE(neighbour.connectTo(station.port()));
    AutoRunProcess run;
    run.start(station.port(), ThreeTrains + QStringList{"--seconds", "60"});
    ASSERT_TRUE(run.waitForEvent("departed", loc(Br218))) << run.log();
    std::set<int> held;
    for (const QJsonObject& event : run.events())
        if (event["loc"] == loc(Br218) &&
            (event["event"] == "placed" || event["event"] == "reserved" || event["event"] == "entered"))
            held.insert(event["block"].toInt());
    // Its departure confirmed first: the station carries out the commands in the order they reach it.
    ASSERT_TRUE(support::runEventsUntil([&] { return neighbour.stationSpeed(Br218) > 0; }, 5000));
    const std::size_t manualMark = neighbour.mark();
    neighbour.send(cs2::LocoSpeed{cs2::LocId(Br218), 0});
    ASSERT_TRUE(run.waitForEvent("manual", loc(Br218), 5000)) << run.log();
    const std::size_t manualLine = run.events().size();
    const int entered = run.count("entered");
    ASSERT_TRUE(run.waitFor([&](const QJsonObject&) { return run.count("entered") >= entered + 2; }, 40000))
        << run.log();
    run.interrupt();
    EXPECT_EQ(run.ended(), 0) << run.log();
    for (std::size_t i = manualLine; i < run.events().size(); ++i) {
        const QJsonObject& event = run.events()[i];
        if (event["event"] == "entered" && event["loc"] != loc(Br218)) {
            EXPECT_FALSE(held.contains(event["block"].toInt())) << run.log();
        }
    }
    EXPECT_EQ(neighbour.speedsAboveZeroAfterStop(Br218, manualMark), 0) << "the automation drives it no more";
    EXPECT_EQ(neighbour.stationSpeed(Br218), 0);
    EXPECT_EQ(station.accidents(), 0) << station.program().output().toStdString();
}

// Another program throws turnout 2 while the BR 218's way over it is reserved: the train stops, the fault
// is printed, and the run ends not acknowledged.
TEST(AutoRunFaults, AnExternalSwitchOfAReservedTurnoutStopsTheTrain) {
    ensureApplication();
    DemoStation station(OneTrain);
    ASSERT_NE(station.port(), 0) << station.program().output().toStdString();
    BusNeighbour neighbour;
    ASSERT_TRUE(neighbour.connectTo(station.port()));
    AutoRunProcess run;
    run.start(station.port(), OneTrain + QStringList{"--seconds", "60"});
    ASSERT_TRUE(run.waitForEvent("departed", loc(Br218))) << run.log();
    const std::size_t faultMark = neighbour.mark();
    neighbour.send(cs2::AccessorySwitch{cs2::LocId(0x3001), 0, 1, std::nullopt});
    ASSERT_TRUE(run.waitForEvent("fault", loc(Br218), 5000)) << run.log();
    EXPECT_TRUE(run.waitFor([](const QJsonObject& e) {
        return e["text"].toString().contains("turnout 2 was switched to position 0");
    }));
    EXPECT_TRUE(allStand(neighbour, {Br218}));
    QTest::qWait(2000);
    run.interrupt();
    EXPECT_EQ(run.ended(), 1) << run.log();
    EXPECT_EQ(neighbour.speedsAboveZeroAfterStop(Br218, faultMark), 0);
    EXPECT_EQ(run.summary()["faults"].toInt(), 1) << run.log();
    EXPECT_EQ(station.accidents(), 0) << station.program().output().toStdString();
}

// Another program reports an occupied contact in the block the BR 218 runs to (an unknown occupant): the
// ghost is printed, the train stops at once and stays.
TEST(AutoRunFaults, AGhostOnTheReservedWayStopsTheTrain) {
    ensureApplication();
    DemoStation station(OneTrain);
    ASSERT_NE(station.port(), 0) << station.program().output().toStdString();
    BusNeighbour neighbour;
    ASSERT_TRUE(neighbour.connectTo(station.port()));
    AutoRunProcess run;
    run.start(station.port(), OneTrain + QStringList{"--seconds", "60"});
    QString destination;
    ASSERT_TRUE(run.waitFor([&](const QJsonObject& e) {
        if (AutoRunProcess::isEvent(e, "reserved", loc(Br218)))
            destination = e["blockName"].toString();
        return AutoRunProcess::isEvent(e, "departed", loc(Br218));
    })) << run.log();
    ASSERT_TRUE(DemoContacts.contains(destination)) << destination.toStdString();
    const std::size_t faultMark = neighbour.mark();
    neighbour.send(
        cs2::S88Event{0, DemoContacts.at(destination), std::nullopt, std::nullopt, cs2::S88Change{0, 1, 0}},
        true);
    ASSERT_TRUE(run.waitForEvent("ghost", {}, 5000)) << run.log();
    ASSERT_TRUE(run.waitForEvent("fault", loc(Br218), 5000)) << run.log();
    EXPECT_TRUE(allStand(neighbour, {Br218}));
    QTest::qWait(2000);
    run.interrupt();
    EXPECT_EQ(run.ended(), 1) << run.log();
    EXPECT_EQ(neighbour.speedsAboveZeroAfterStop(Br218, faultMark), 0)
        << neighbour.speedsHeard() << run.log();
    EXPECT_EQ(run.count("entered", loc(Br218)), 0) << run.log();
    EXPECT_EQ(station.accidents(), 0) << station.program().output().toStdString();
}

// The station switches turnout 2 for the BR 218, but its answers never reach the program (the ICE runs
// meanwhile, so the station is heard): after the attempts the train has not moved, its way is given back,
// the fault names the turnout.
TEST(AutoRunFaults, ATurnoutNeverConfirmedKeepsTheTrainAndGivesItsWayBack) {
    ensureApplication();
    DemoStation station(ThreeTrains);
    ASSERT_NE(station.port(), 0) << station.program().output().toStdString();
    FrameEater eater(station.port(), turnout2Answer);
    BusNeighbour neighbour;
    ASSERT_TRUE(neighbour.connectTo(station.port()));
    AutoRunProcess run;
    run.start(eater.port(), ThreeTrains + QStringList{"--seconds", "60"});
    ASSERT_TRUE(run.waitForEvent("reserved", loc(Br218))) << run.log();
    ASSERT_TRUE(run.waitForEvent("fault", loc(Br218), 30000)) << run.log();
    EXPECT_TRUE(run.waitFor([](const QJsonObject& e) {
        return e["text"].toString().contains(QRegularExpression(
            "turnout 2 was not confirmed.*BR 218 Ost does not depart, its way is given back"));
    })) << run.log();
    EXPECT_GT(eater.eaten(), 0);
    EXPECT_EQ(run.count("departed", loc(Br218)), 0) << run.log();
    EXPECT_EQ(linesSaying(run, "turnout 2 confirmed"), 0) << run.log();
    EXPECT_EQ(neighbour.speedsAboveZeroAfterStop(Br218), 0) << "the train does not depart";
    EXPECT_EQ(neighbour.stationSpeed(Br218), 0);
    run.interrupt();
    EXPECT_EQ(run.ended(), 1) << run.log();
    EXPECT_GE(run.summary()["faults"].toInt(), 1) << run.log();
    EXPECT_EQ(station.accidents(), 0) << station.program().output().toStdString();
}

// The contacts of Ausfahrt Ost and Block 1 are dead (their reports never reach the program): the BR 218,
// on its way to Block 1 over Ausfahrt Ost, is never seen arriving; in the time its speed and the distance
// give it is lost: stopped, and the program says to place it again.
TEST(AutoRunFaults, ATrainNotSeenArrivingInTimeIsLostAndStopped) {
    ensureApplication();
    DemoStation station(OneTrain);
    ASSERT_NE(station.port(), 0) << station.program().output().toStdString();
    FrameEater eater(station.port(), deadContactReport);
    BusNeighbour neighbour;
    ASSERT_TRUE(neighbour.connectTo(station.port()));
    AutoRunProcess run;
    run.start(eater.port(), OneTrain + QStringList{"--seconds", "60"});
    ASSERT_TRUE(run.waitForEvent("departed", loc(Br218))) << run.log();
    const std::size_t departedMark = neighbour.mark();
    ASSERT_TRUE(run.waitForEvent("lost", loc(Br218), 30000)) << run.log();
    EXPECT_TRUE(
        run.waitFor([](const QJsonObject& e) { return e["text"].toString().contains("place it again"); }));
    EXPECT_TRUE(allStand(neighbour, {Br218}));
    EXPECT_GT(eater.eaten(), 0);
    run.interrupt();
    EXPECT_EQ(run.ended(), 1) << run.log();
    EXPECT_EQ(neighbour.speedsAboveZeroAfterStop(Br218, departedMark), 0) << neighbour.speedsHeard();
    EXPECT_EQ(run.summary()["faults"].toInt(), 1) << run.log();
    EXPECT_EQ(station.accidents(), 0) << station.program().output().toStdString();
}

// Junk on the program's connection every 100 ms while the three trains run (frames with a DLC above 8, a
// broken gateway's bytes): dropped, and the trains run on without accident or fault.
TEST(AutoRunFaults, GarbageOnTheBusWhileTrainsRunChangesNothing) {
    ensureApplication();
    DemoStation station(ThreeTrains);
    ASSERT_NE(station.port(), 0) << station.program().output().toStdString();
    e2e::JunkRelay relay(station.port());
    ASSERT_TRUE(relay.listening());
    AutoRunProcess run;
    run.start(relay.port(), ThreeTrains + QStringList{"--seconds", "12"});
    QTimer junk;
    QObject::connect(&junk, &QTimer::timeout, [&] { relay.injectToApp(QByteArray(26, '\xFF')); });
    junk.start(100);
    EXPECT_EQ(run.ended(40000), 0) << run.log();
    junk.stop();
    const QJsonObject summary = run.summary();
    EXPECT_EQ(summary["faults"].toInt(-1), 0) << run.log();
    EXPECT_GE(summary["blockMoves"].toInt(), 3) << run.log();
    EXPECT_EQ(relay.connections(), 1) << "junk does not break the connection";
    EXPECT_EQ(station.accidents(), 0) << station.program().output().toStdString();
}

// Until `trains` of the run have departed (so that they are running when the fault comes).
bool trainsDeparted(AutoRunProcess& run, int trains) {
    return run.waitFor(
        [&](const QJsonObject&) {
            int departed = 0;
            for (const std::uint32_t train : {Br218, Ice, V100})
                departed += run.count("departed", loc(train)) > 0;
            return departed >= trains;
        },
        40000);
}

// The station stalls (SIGSTOP) while the trains run, for 1 s or for 20 s, then goes on. Long enough to be
// noticed as silence, the automation pauses and says every train is stopped-unknown; when the station is
// back, every train is told to stop (or is lost: the station kept it running, and it is not where it was)
// and stays: nothing departs again, no speed above 0 reaches the station.
// Too short to be noticed, the run goes on as if nothing happened. Either way no accident, and the
// station ends with every train standing.
class AutoRunStall : public ::testing::TestWithParam<int> {};

TEST_P(AutoRunStall, TheTrainsStandAfterTheOutageAndNothingIsReplayed) {
    const int stallMs = GetParam();
    ensureApplication();
    DemoStation station(ThreeTrains);
    ASSERT_NE(station.port(), 0) << station.program().output().toStdString();
    BusNeighbour neighbour;
    ASSERT_TRUE(neighbour.connectTo(station.port()));
    AutoRunProcess run;
    run.start(station.port(), ThreeTrains + QStringList{"--seconds", "120"});
    ASSERT_TRUE(trainsDeparted(run, 2)) << run.log();
    const std::size_t before = run.events().size();
    ASSERT_TRUE(station.program().stall());
    QTest::qWait(stallMs);
    ASSERT_TRUE(station.program().wake());
    const std::size_t wokeMark = neighbour.mark();
    if (stallMs >= 10000) {
        ASSERT_TRUE(run.waitFor(
            [&](const QJsonObject&) { return linesSaying(run, "stopped-unknown", before) >= 3; }, 10000))
            << run.log();
        ASSERT_TRUE(
            run.waitFor([&](const QJsonObject&) { return everyTrainStoppedOnReturn(run, before); }, 20000))
            << run.log();
        EXPECT_TRUE(allStand(neighbour, {Br218, Ice, V100}, 10000));
        const std::size_t back = run.events().size();
        QTest::qWait(3000);
        for (std::size_t i = back; i < run.events().size(); ++i)
            EXPECT_NE(run.events()[i]["event"].toString(), "departed") << run.log();
        for (const std::uint32_t train : {Br218, Ice, V100})
            EXPECT_EQ(neighbour.speedsAboveZeroAfterStop(train, wokeMark), 0) << train;
    } else {
        const int entered = run.count("entered");
        EXPECT_TRUE(
            run.waitFor([&](const QJsonObject&) { return run.count("entered") >= entered + 3; }, 30000))
            << run.log();
    }
    run.interrupt();
    run.ended();
    EXPECT_EQ(run.summary()["event"].toString(), "summary") << run.log();
    EXPECT_TRUE(allStand(neighbour, {Br218, Ice, V100}, 10000));
    EXPECT_EQ(station.accidents(), 0) << station.program().output().toStdString();
    std::cout << "    " << stallMs / 1000 << " s: " << linesSaying(run, "stopped-unknown", before)
              << " stopped-unknown lines" << std::endl;
}

INSTANTIATE_TEST_SUITE_P(Outage, AutoRunStall, ::testing::Values(1000, 20000),
                         [](const auto& info) { return "For" + std::to_string(info.param / 1000) + "s"; });

// The station is killed while the trains run and started again on the same port (its trains back where
// they were placed, standing): the program says every train is stopped-unknown, reads the contacts again
// (trains not where it saw them are lost, occupants it cannot explain are ghosts) and moves nothing.
TEST(AutoRunFaults, AStationKilledAndStartedAgainMovesNothing) {
    ensureApplication();
    const std::uint16_t port = freePort();
    auto station = std::make_unique<DemoStation>(ThreeTrains, port);
    ASSERT_EQ(station->port(), port) << station->program().output().toStdString();
    AutoRunProcess run;
    run.start(port, ThreeTrains + QStringList{"--seconds", "120"});
    ASSERT_TRUE(trainsDeparted(run, 2)) << run.log();
    EXPECT_EQ(station->accidents(), 0);
    const std::size_t before = run.events().size();
    station.reset();
    ASSERT_TRUE(run.waitFor(
        [&](const QJsonObject&) { return linesSaying(run, "stopped-unknown", before) >= 3; }, 10000))
        << run.log();
    station = std::make_unique<DemoStation>(ThreeTrains, port);
    ASSERT_EQ(station->port(), port) << station->program().output().toStdString();
    BusNeighbour neighbour;
    ASSERT_TRUE(neighbour.connectTo(port));
    ASSERT_TRUE(
        run.waitFor([&](const QJsonObject&) { return everyTrainStoppedOnReturn(run, before); }, 30000))
        << run.log();
    const std::size_t back = run.events().size();
    QTest::qWait(3000);
    for (std::size_t i = back; i < run.events().size(); ++i)
        EXPECT_NE(run.events()[i]["event"].toString(), "departed") << run.log();
    for (const std::uint32_t train : {Br218, Ice, V100})
        EXPECT_EQ(neighbour.speedsAboveZero(train), 0) << train;
    EXPECT_TRUE(allStand(neighbour, {Br218, Ice, V100}));
    run.interrupt();
    run.ended();
    EXPECT_EQ(run.summary()["event"].toString(), "summary") << run.log();
    EXPECT_EQ(station->accidents(), 0) << station->program().output().toStdString();
}

} // namespace
} // namespace stellwerk::cli
