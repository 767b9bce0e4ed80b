// `stellwerk-cli --station URL serve --z21 HOST:PORT` / `--withrottle HOST:PORT` against the real
// stellwerk-sim: a Z21 or WiThrottle client of the tests' own drives the demo's MM loco 24 on its address 24,
// the command prints one line per client event, and ends after --seconds with exit 0, or on Ctrl+C (SIGINT),
// leaving every locomotive its clients drove standing at the station.

#include "../core/withrottleserver/WiThrottleTestClient.h"
#include "../core/z21server/Z21TestClient.h"
#include "CliApplication.h"
#include "SimProgram.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTcpServer>
#include <QUdpSocket>
#include <csignal>
#include <gtest/gtest.h>

namespace stellwerk::cli {
namespace {

quint16 freeTcpPort() {
    QTcpServer server;
    server.listen(QHostAddress::LocalHost, 0);
    return server.serverPort();
}

quint16 freeUdpPort() {
    QUdpSocket socket;
    socket.bind(QHostAddress::LocalHost, 0);
    return socket.localPort();
}

// The real stellwerk-sim on loopback and `stellwerk-cli serve` in front of it with the given options, and
// what serve printed so far.
class ServeRig {
public:
    explicit ServeRig(const QStringList& serveOptions)
        : sim(QStringList{"--listen", "127.0.0.1", "--udp-port", "0", "--udp-reply-host", "127.0.0.1",
                          "--tcp-port", "0", "--http-port", "0"}) {
        cli.start(STELLWERK_CLI,
                  QStringList{"--station", QStringLiteral("tcp://127.0.0.1:%1").arg(sim.tcpPort()), "serve"} +
                      serveOptions);
    }
    // Waits until serve has printed `text`.
    bool printed(const char* text) {
        return support::runEventsUntil(
            [&] {
                out += cli.readAllStandardOutput();
                return out.contains(text);
            },
            15000);
    }
    bool ended() {
        const bool done = support::runEventsUntil([&] { return cli.state() == QProcess::NotRunning; }, 20000);
        out += cli.readAllStandardOutput();
        return done;
    }
    std::string said() { return out.toStdString() + cli.readAllStandardError().toStdString(); }

    support::SimProgram sim;
    QProcess cli;
    QByteArray out;
};

// A Z21 client of the tests' own drives loco 24 at step 40 through serve's Z21 server; true once the
// station's confirmed speed has come back to it.
bool z21DrivesLoco24(z21server::test::Z21TestClient& phone) {
    phone.send(z21::SetBroadcastFlags{z21::broadcast::DrivingAndSwitching});
    phone.send(z21::SetLocoDrive{24, {z21::SpeedStepMode::Steps128, true, 40, false}});
    return support::runEventsUntil(
        [&] {
            const auto info = phone.locoInfo(24);
            return info && info->speed.step == 40;
        },
        10000);
}

TEST(ServeCommand, AZ21ClientDrivesTheDemosLocoAndEachClientEventIsALine) {
    test::ensureApplication();
    const quint16 z21Port = freeUdpPort();
    ServeRig rig({"--z21", QStringLiteral("127.0.0.1:%1").arg(z21Port), "--seconds", "6", "--json"});
    ASSERT_NE(rig.sim.tcpPort(), 0) << rig.sim.output().toStdString();
    ASSERT_TRUE(rig.printed("\"listening\"")) << rig.said();
    z21server::test::Z21TestClient phone(z21Port);
    EXPECT_TRUE(z21DrivesLoco24(phone)) << "the station confirmed the speed";
    ASSERT_TRUE(rig.printed("\"drove\"")) << rig.said();
    ASSERT_TRUE(rig.ended());
    EXPECT_EQ(rig.cli.exitCode(), 0);
    const QList<QByteArray> lines = rig.out.trimmed().split('\n');
    ASSERT_GE(lines.size(), 3);
    const QJsonObject joined = QJsonDocument::fromJson(lines.at(1)).object();
    EXPECT_EQ(joined["event"].toString(), "joined");
    EXPECT_EQ(joined["client"].toString(), QStringLiteral("z21 127.0.0.1:%1").arg(phone.localPort()));
}

TEST(ServeCommand, AWiThrottleClientDrivesTheDemosLocoAndLeavingStopsIt) {
    test::ensureApplication();
    const quint16 port = freeTcpPort();
    ServeRig rig({"--withrottle", QStringLiteral("127.0.0.1:%1").arg(port), "--seconds", "6"});
    ASSERT_NE(rig.sim.tcpPort(), 0) << rig.sim.output().toStdString();
    ASSERT_TRUE(rig.printed("listening: server (WiThrottle on 127.0.0.1:")) << rig.said();
    auto phone = std::make_unique<withrottleserver::test::WiThrottleTestClient>(port);
    phone->send(withrottle::DeviceName{"cli-phone"});
    phone->send(withrottle::AcquireLoco{'T', "S24", withrottle::LocoAddress{24, false}, false});
    ASSERT_TRUE(rig.printed("acquired: withrottle 127.0.0.1:")) << rig.said();
    phone->send(withrottle::ThrottleAction{'T', "S24", withrottle::SetSpeed{40}});
    EXPECT_TRUE(support::runEventsUntil([&] { return phone->speedOf("S24") == 40; }, 10000))
        << "the station confirmed the speed";
    phone->close();
    ASSERT_TRUE(rig.printed("left: withrottle 127.0.0.1:")) << rig.said();
    EXPECT_TRUE(rig.out.contains("(stopped 0x0018)")) << rig.said();
    ASSERT_TRUE(rig.ended());
    EXPECT_EQ(rig.cli.exitCode(), 0);
    EXPECT_TRUE(rig.out.contains("named: withrottle 127.0.0.1:")) << rig.said();
    EXPECT_TRUE(rig.out.contains("mdns: server (")) << "announced, or the log says why not";
}

// What the station itself says of the demo's loco 24 (`resync` asks the station and prints each loco).
QString stationLine24(quint16 stationPort) {
    QProcess resync;
    resync.start(STELLWERK_CLI,
                 QStringList{"--station", QStringLiteral("tcp://127.0.0.1:%1").arg(stationPort), "resync"});
    if (!resync.waitForFinished(20000))
        return {};
    for (const QString& line : QString::fromUtf8(resync.readAllStandardOutput()).split('\n'))
        if (line.contains("(0x0018):"))
            return line;
    return {};
}

TEST(ServeCommand, CtrlCEndsItAndStopsTheLocomotivesItsClientsDrove) {
    test::ensureApplication();
    const quint16 z21Port = freeUdpPort();
    ServeRig rig({"--z21", QStringLiteral("127.0.0.1:%1").arg(z21Port), "--seconds", "120"});
    ASSERT_NE(rig.sim.tcpPort(), 0) << rig.sim.output().toStdString();
    ASSERT_TRUE(rig.printed("listening: ")) << rig.said();
    z21server::test::Z21TestClient phone(z21Port);
    ASSERT_TRUE(z21DrivesLoco24(phone)) << "the station confirmed the speed";
    ASSERT_FALSE(stationLine24(rig.sim.tcpPort()).contains(": speed 0,")) << "the loco runs before Ctrl+C";

    ::kill(pid_t(rig.cli.processId()), SIGINT);
    ASSERT_TRUE(rig.ended()) << "Ctrl+C ends serve long before its 120 s";
    EXPECT_EQ(rig.cli.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(rig.cli.exitCode(), 0);
    EXPECT_TRUE(stationLine24(rig.sim.tcpPort()).contains(": speed 0,"))
        << "the station ends with the phone's loco standing: "
        << stationLine24(rig.sim.tcpPort()).toStdString();
}

} // namespace
} // namespace stellwerk::cli
