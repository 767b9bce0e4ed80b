#include "connection/StationConnection.h"

#include "ConnectionWaits.h"
#include "EmbeddedStationSupport.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"

#include <QEventLoop>
#include <QSignalSpy>
#include <QTimer>
#include <QUdpSocket>
#include <algorithm>
#include <gtest/gtest.h>
#include <memory>
#include <utility>
#include <vector>

using namespace stellwerk;
using connection::ConnectionBuses;
using connection::LoadingProgress;
using connection::LoadingStep;
using connection::StationConnection;
using State = StationConnection::State;

using namespace stellwerk::connection::test;

namespace {

// Every state the connection went through, in order.
class StateRecorder {
public:
    explicit StateRecorder(StationConnection& connection) {
        QObject::connect(&connection, &StationConnection::stateChanged, &context_,
                         [this](State state) { states.push_back(state); });
    }
    bool saw(State state) const { return std::find(states.begin(), states.end(), state) != states.end(); }

    std::vector<State> states;

private:
    QObject context_;
};

// Runs the event loop until the connection reaches `state` (a real loop: the start-up's many round trips
// would crawl under QTest::qWaitFor's sleeps).
bool waitForState(const StationConnection& connection, State state, int timeoutMs = ReadyMs) {
    if (connection.state() == state)
        return true;
    QEventLoop loop;
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    QObject::connect(&connection, &StationConnection::stateChanged, &loop, [&loop, state](State reached) {
        if (reached == state)
            loop.quit();
    });
    loop.exec();
    return connection.state() == state;
}

// A free port for UDP on the loopback address (bound once, then released for the code under test).
std::uint16_t freeUdpPort() {
    QUdpSocket socket;
    socket.bind(QHostAddress::LocalHost, 0);
    return socket.localPort();
}

// A simulated CS2 with the demo layout behind a server on the loopback address, as the test starts it.
class TestStation {
public:
    TestStation() : station_(sim::StationLayout::demo()) {}

    bool start(std::uint16_t tcpPort = 0) {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress(QHostAddress::LocalHost);
        settings.udp = false;
        settings.tcpPort = tcpPort;
        server_ = std::make_unique<sim::StationServer>(station_, settings);
        return server_->listen();
    }
    bool startUdp(std::uint16_t udpPort, std::uint16_t replyPort) {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress(QHostAddress::LocalHost);
        settings.tcp = false;
        settings.udpPort = udpPort;
        settings.udpReplyHost = QHostAddress(QHostAddress::LocalHost);
        settings.udpReplyPort = replyPort;
        server_ = std::make_unique<sim::StationServer>(station_, settings);
        return server_->listen();
    }
    void stop() { server_.reset(); }
    std::uint16_t tcpPort() const { return server_->tcpPort(); }
    std::uint16_t udpPort() const { return server_->udpPort(); }

private:
    sim::SimulatedStation station_;
    std::unique_ptr<sim::StationServer> server_;
};

// Pings twice a second and calls the station silent after the third missed one, so that tests are quick.
connection::ConnectionSettings quickLiveness() {
    connection::ConnectionSettings settings;
    settings.session.liveness.interval = std::chrono::milliseconds(200);
    return settings;
}

} // namespace

TEST(StationConnection, StartsDisconnected) {
    StationConnection connection{support::withEmbeddedStation()};
    EXPECT_EQ(connection.state(), State::Disconnected);
    EXPECT_EQ(connection.session(), nullptr);
}

TEST(StationConnection, NoAddressStartsTheEmbeddedDemoStationAndBecomesReady) {
    StationConnection connection{support::withEmbeddedStation()};
    StateRecorder recorder(connection);
    connection.connectTo(QString());
    EXPECT_EQ(connection.description(), QStringLiteral("Simulated CS2 (demo layout)"));
    EXPECT_NE(connection.embeddedPort(), 0);
    ASSERT_TRUE(waitForState(connection, State::Ready)) << connection.lastProblem().toStdString();
    EXPECT_EQ(recorder.states, (std::vector{State::Connecting, State::LoadingConfiguration, State::Ready}));
}

// The connection layer never links the simulator: a program that hands over no local station gets a clear
// reason instead of a demo.
TEST(StationConnection, WithoutALocalStationTheSimulatedOneFailsWithTheReason) {
    StationConnection connection;
    QSignalSpy problems(&connection, &StationConnection::problem);
    connection.connectToSimulator();
    EXPECT_EQ(connection.state(), State::Failed);
    EXPECT_EQ(connection.failureReason(), QStringLiteral("this program has no simulated station"));
    EXPECT_EQ(connection.embeddedPort(), 0);
}

TEST(StationConnection, EmbeddedStationHasTheDemoLayoutsCounts) {
    StationConnection connection{support::withEmbeddedStation()};
    connection.connectToSimulator();
    ASSERT_TRUE(waitForState(connection, State::Ready));
    const sim::StationLayout demo = sim::StationLayout::demo();
    const connection::StationCounts counts = connection.counts();
    EXPECT_EQ(counts.locomotives, 12);
    EXPECT_EQ(counts.accessories, int(demo.accessories().accessories.size()));
    EXPECT_EQ(counts.routes, int(demo.routes().routes.size()));
    EXPECT_EQ(counts.pages, 3);
    EXPECT_GE(counts.devices, 1); // the CS2 itself answers the ping
    EXPECT_TRUE(connection.startupResult().problems.isEmpty())
        << connection.startupResult().problems.join(QLatin1Char('\n')).toStdString();
}

TEST(StationConnection, CountsTheFramesOfItsTransportAndZerosWithoutOne) {
    StationConnection connection{support::withEmbeddedStation()};
    EXPECT_EQ(connection.buses().stationCounters().framesIn, 0u);
    connection.connectToSimulator();
    ASSERT_TRUE(waitForState(connection, State::Ready));
    const transport::TransportCounters counters = connection.buses().stationCounters();
    EXPECT_GT(counters.framesOut, 10u);               // pings, config requests, state queries
    EXPECT_GT(counters.framesIn, counters.framesOut); // every request has an answer, downloads have many
    connection.disconnectFromStation();
    EXPECT_EQ(connection.buses().stationCounters().framesOut, 0u);
}

TEST(StationConnection, ProgressNamesTheStepsAndTheFilesWithTheirPercentage) {
    StationConnection connection{support::withEmbeddedStation()};
    std::vector<LoadingProgress> seen;
    QObject::connect(&connection, &StationConnection::progressChanged,
                     [&seen](const LoadingProgress& progress) { seen.push_back(progress); });
    connection.connectToSimulator();
    ASSERT_TRUE(waitForState(connection, State::Ready));
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.front().step, LoadingStep::ListingDevices);
    EXPECT_EQ(seen.front().stepNumber, 1);
    EXPECT_EQ(seen.front().stepCount, 5);
    EXPECT_EQ(seen.back().step, LoadingStep::ReadingStates);
    const auto locos = std::find_if(seen.begin(), seen.end(), [](const LoadingProgress& progress) {
        return progress.file == QStringLiteral("lokomotive.cs2") && progress.percent() == 100;
    });
    ASSERT_NE(locos, seen.end());
    EXPECT_EQ(locos->step, LoadingStep::DownloadingFiles);
    EXPECT_EQ(locos->fileNumber, 1);
    EXPECT_GE(locos->fileCount, 4); // locos, accessories, routes, track plan (and then its pages)
}

TEST(StationConnection, SessionStartsBeforeTheStartupAndTheConfigurationArrivesBeforeReady) {
    StationConnection connection{support::withEmbeddedStation()};
    std::vector<QString> events;
    QObject::connect(&connection, &StationConnection::sessionStarted, [&](station::StationSession* session) {
        events.push_back(session == connection.session() ? QStringLiteral("session") : QStringLiteral("?"));
    });
    QObject::connect(&connection, &StationConnection::configurationLoaded,
                     [&](const station::StartupResult& result) {
                         events.push_back(QStringLiteral("loaded %1").arg(result.files.count("loks")));
                     });
    QObject::connect(&connection, &StationConnection::stateChanged, [&](State state) {
        if (state == State::Ready)
            events.push_back(QStringLiteral("ready"));
    });
    connection.connectToSimulator();
    ASSERT_TRUE(waitForState(connection, State::Ready));
    EXPECT_EQ(events, (std::vector<QString>{QStringLiteral("session"), QStringLiteral("loaded 1"),
                                            QStringLiteral("ready")}));
}

TEST(StationConnection, AnAddressThatCannotBeReadFailsWithTheReason) {
    StationConnection connection{support::withEmbeddedStation()};
    QSignalSpy problems(&connection, &StationConnection::problem);
    connection.connectTo(QStringLiteral("http://cs2"));
    EXPECT_EQ(connection.state(), State::Failed);
    EXPECT_EQ(connection.description(), QStringLiteral("Station \"http://cs2\""));
    EXPECT_TRUE(connection.failureReason().contains(QStringLiteral("http")))
        << connection.failureReason().toStdString();
    EXPECT_EQ(connection.session(), nullptr);
    ASSERT_EQ(problems.count(), 1);
    EXPECT_TRUE(problems.at(0).at(0).toString().contains(connection.failureReason()));
}

TEST(StationConnection, AnAddressWithoutHostFails) {
    StationConnection connection{support::withEmbeddedStation()};
    connection.connectTo(QStringLiteral("udp://"));
    EXPECT_EQ(connection.state(), State::Failed);
    EXPECT_FALSE(connection.failureReason().isEmpty());
}

TEST(StationConnection, TcpAddressOfAStationServerBecomesReady) {
    TestStation station;
    ASSERT_TRUE(station.start());
    StationConnection connection{support::withEmbeddedStation()};
    connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(station.tcpPort()));
    EXPECT_EQ(connection.description(), QStringLiteral("CS2 at 127.0.0.1:%1 (TCP)").arg(station.tcpPort()));
    EXPECT_EQ(connection.embeddedPort(), 0);
    ASSERT_TRUE(waitForState(connection, State::Ready)) << connection.lastProblem().toStdString();
    EXPECT_EQ(connection.counts().locomotives, 12);
}

// The bus monitor's view: the start-up's ping goes out as an outgoing frame before its answer comes in.
TEST(StationConnection, FramesSeenReportsWhatWasSentAndWhatCameBack) {
    TestStation station;
    ASSERT_TRUE(station.start());
    StationConnection connection{support::withEmbeddedStation()};
    std::vector<std::pair<bool, can::CanFrame>> seen;
    QObject::connect(&connection.buses(), &ConnectionBuses::stationFramesSeen,
                     [&seen](const std::vector<can::CanFrame>& frames, bool outgoing) {
                         for (const can::CanFrame& frame : frames)
                             seen.emplace_back(outgoing, frame);
                     });
    connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(station.tcpPort()));
    ASSERT_TRUE(waitForState(connection, State::Ready)) << connection.lastProblem().toStdString();
    const auto firstOut = std::find_if(seen.begin(), seen.end(), [](const auto& s) { return s.first; });
    ASSERT_NE(firstOut, seen.end());
    EXPECT_FALSE(cs2::isResponse(firstOut->second));
    const auto answer = std::find_if(firstOut, seen.end(), [&](const auto& s) {
        return !s.first && cs2::isResponse(s.second) &&
               cs2::command(s.second) == cs2::command(firstOut->second);
    });
    EXPECT_NE(answer, seen.end()) << "the station answers what we sent";
    const auto outgoing = std::count_if(seen.begin(), seen.end(), [](const auto& s) { return s.first; });
    EXPECT_GT(outgoing, 5) << "the start-up asks for devices, files and states";
}

TEST(StationConnection, NoServerListeningStaysConnectingAndSaysWhy) {
    TestStation station;
    ASSERT_TRUE(station.start());
    const std::uint16_t port = station.tcpPort();
    station.stop(); // a port nobody listens on
    StationConnection connection{support::withEmbeddedStation()};
    QSignalSpy problems(&connection, &StationConnection::problem);
    connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(port));
    ASSERT_TRUE(problems.wait(ReadyMs));
    EXPECT_EQ(connection.state(), State::Connecting);
    EXPECT_TRUE(connection.lastProblem().contains(QStringLiteral("trying again")))
        << connection.lastProblem().toStdString();
}

TEST(StationConnection, StoppedServerMakesTheStationSilentAndARestartLoadsAgain) {
    TestStation station;
    ASSERT_TRUE(station.start());
    const std::uint16_t port = station.tcpPort();
    StationConnection connection{support::withEmbeddedStation()};
    connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(port));
    ASSERT_TRUE(waitForState(connection, State::Ready));

    station.stop();
    ASSERT_TRUE(waitForState(connection, State::Silent, 5000));
    StateRecorder recorder(connection);
    QSignalSpy loaded(&connection, &StationConnection::configurationLoaded);
    ASSERT_TRUE(station.start(port));
    ASSERT_TRUE(waitForState(connection, State::Ready)) << connection.lastProblem().toStdString();
    EXPECT_EQ(recorder.states, (std::vector{State::LoadingConfiguration, State::Ready}));
    EXPECT_EQ(loaded.count(), 1);
    EXPECT_EQ(connection.counts().locomotives, 12);
}

TEST(StationConnection, UdpStationThatStopsAnsweringPingsIsSilentAndReadyAgainWhenBack) {
    const std::uint16_t listenPort = freeUdpPort();
    TestStation station;
    ASSERT_TRUE(station.startUdp(0, listenPort));
    const std::uint16_t stationPort = station.udpPort();
    StationConnection connection(support::withEmbeddedStation(quickLiveness()));
    connection.connectTo(QStringLiteral("udp://127.0.0.1:%1?listen=%2").arg(stationPort).arg(listenPort));
    ASSERT_TRUE(waitForState(connection, State::Ready)) << connection.lastProblem().toStdString();

    station.stop();
    ASSERT_TRUE(waitForState(connection, State::Silent, 5000));
    ASSERT_TRUE(station.startUdp(stationPort, listenPort));
    ASSERT_TRUE(waitForState(connection, State::Ready)) << connection.lastProblem().toStdString();
}

TEST(StationConnection, ConnectingElsewhereEndsTheEmbeddedStation) {
    StationConnection connection{support::withEmbeddedStation()};
    connection.connectToSimulator();
    ASSERT_TRUE(waitForState(connection, State::Ready));
    connection.connectTo(QStringLiteral("http://cs2"));
    EXPECT_EQ(connection.state(), State::Failed);
    EXPECT_EQ(connection.embeddedPort(), 0);
    connection.disconnectFromStation();
    EXPECT_EQ(connection.state(), State::Disconnected);
    EXPECT_TRUE(connection.failureReason().isEmpty());
}
