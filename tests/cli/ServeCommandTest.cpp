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

TEST(ServeCommand, AZ21ClientDrivesTheDemosLocoAndEachClientEventIsALine) {
    test::ensureApplication();
    support::SimProgram sim(QStringList{"--listen", "127.0.0.1", "--udp-port", "0", "--udp-reply-host",
                                        "127.0.0.1", "--tcp-port", "0", "--http-port", "0"});
    ASSERT_NE(sim.tcpPort(), 0) << sim.output().toStdString();
    const quint16 z21Port = freeUdpPort();
    QProcess cli;
    cli.start(STELLWERK_CLI,
              QStringList{"--station", QStringLiteral("tcp://127.0.0.1:%1").arg(sim.tcpPort()), "serve",
                          "--z21", QStringLiteral("127.0.0.1:%1").arg(z21Port), "--seconds", "6", "--json"});
    QByteArray out;
    const auto printed = [&](const char* text) {
        return support::runEventsUntil(
            [&] {
                out += cli.readAllStandardOutput();
                return out.contains(text);
            },
            15000);
    };
    ASSERT_TRUE(printed("\"listening\"")) << out.toStdString() << cli.readAllStandardError().toStdString();
    z21server::test::Z21TestClient phone(z21Port);
    phone.send(z21::SetBroadcastFlags{z21::broadcast::DrivingAndSwitching});
    phone.send(z21::SetLocoDrive{24, {z21::SpeedStepMode::Steps128, true, 40, false}});
    ASSERT_TRUE(printed("\"drove\"")) << out.toStdString();
    EXPECT_TRUE(support::runEventsUntil(
        [&] {
            const auto info = phone.locoInfo(24);
            return info && info->speed.step == 40;
        },
        10000))
        << "the station confirmed the speed";
    ASSERT_TRUE(support::runEventsUntil([&] { return cli.state() == QProcess::NotRunning; }, 20000));
    out += cli.readAllStandardOutput();
    EXPECT_EQ(cli.exitCode(), 0);
    const QList<QByteArray> lines = out.trimmed().split('\n');
    ASSERT_GE(lines.size(), 3);
    const QJsonObject joined = QJsonDocument::fromJson(lines.at(1)).object();
    EXPECT_EQ(joined["event"].toString(), "joined");
    EXPECT_EQ(joined["client"].toString(), QStringLiteral("z21 127.0.0.1:%1").arg(phone.localPort()));
}

TEST(ServeCommand, AWiThrottleClientDrivesTheDemosLocoAndLeavingStopsIt) {
    test::ensureApplication();
    support::SimProgram sim(QStringList{"--listen", "127.0.0.1", "--udp-port", "0", "--udp-reply-host",
                                        "127.0.0.1", "--tcp-port", "0", "--http-port", "0"});
    ASSERT_NE(sim.tcpPort(), 0) << sim.output().toStdString();
    const quint16 port = freeTcpPort();
    QProcess cli;
    cli.start(STELLWERK_CLI,
              QStringList{"--station", QStringLiteral("tcp://127.0.0.1:%1").arg(sim.tcpPort()), "serve",
                          "--withrottle", QStringLiteral("127.0.0.1:%1").arg(port), "--seconds", "6"});
    QByteArray out;
    const auto printed = [&](const char* text) {
        return support::runEventsUntil(
            [&] {
                out += cli.readAllStandardOutput();
                return out.contains(text);
            },
            15000);
    };
    ASSERT_TRUE(printed("listening: server (WiThrottle on 127.0.0.1:"))
        << out.toStdString() << cli.readAllStandardError().toStdString();
    auto phone = std::make_unique<withrottleserver::test::WiThrottleTestClient>(port);
    phone->send(withrottle::DeviceName{"cli-phone"});
    phone->send(withrottle::AcquireLoco{'T', "S24", withrottle::LocoAddress{24, false}, false});
    ASSERT_TRUE(printed("acquired: withrottle 127.0.0.1:")) << out.toStdString();
    phone->send(withrottle::ThrottleAction{'T', "S24", withrottle::SetSpeed{40}});
    EXPECT_TRUE(support::runEventsUntil([&] { return phone->speedOf("S24") == 40; }, 10000))
        << "the station confirmed the speed";
    phone->close();
    ASSERT_TRUE(printed("left: withrottle 127.0.0.1:")) << out.toStdString();
    EXPECT_TRUE(out.contains("(stopped 0x0018)")) << out.toStdString();
    ASSERT_TRUE(support::runEventsUntil([&] { return cli.state() == QProcess::NotRunning; }, 20000));
    EXPECT_EQ(cli.exitCode(), 0);
    EXPECT_TRUE(out.contains("named: withrottle 127.0.0.1:")) << out.toStdString();
    EXPECT_TRUE(out.contains("mdns: server (")) << "announced, or the log says why not";
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
    support::SimProgram sim(QStringList{"--listen", "127.0.0.1", "--udp-port", "0", "--udp-reply-host",
                                        "127.0.0.1", "--tcp-port", "0", "--http-port", "0"});
    ASSERT_NE(sim.tcpPort(), 0) << sim.output().toStdString();
    const quint16 z21Port = freeUdpPort();
    QProcess cli;
    cli.start(STELLWERK_CLI,
              QStringList{"--station", QStringLiteral("tcp://127.0.0.1:%1").arg(sim.tcpPort()), "serve",
                          "--z21", QStringLiteral("127.0.0.1:%1").arg(z21Port), "--seconds", "120"});
    QByteArray out;
    ASSERT_TRUE(support::runEventsUntil(
        [&] {
            out += cli.readAllStandardOutput();
            return out.contains("listening: ");
        },
        15000))
        << out.toStdString() << cli.readAllStandardError().toStdString();
    z21server::test::Z21TestClient phone(z21Port);
    phone.send(z21::SetBroadcastFlags{z21::broadcast::DrivingAndSwitching});
    phone.send(z21::SetLocoDrive{24, {z21::SpeedStepMode::Steps128, true, 40, false}});
    ASSERT_TRUE(support::runEventsUntil(
        [&] {
            const auto info = phone.locoInfo(24);
            return info && info->speed.step == 40;
        },
        10000))
        << "the station confirmed the speed";
    ASSERT_FALSE(stationLine24(sim.tcpPort()).contains(": speed 0,")) << "the loco runs before Ctrl+C";

    ::kill(pid_t(cli.processId()), SIGINT);
    ASSERT_TRUE(support::runEventsUntil([&] { return cli.state() == QProcess::NotRunning; }, 10000))
        << "Ctrl+C ends serve long before its 120 s";
    EXPECT_EQ(cli.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(cli.exitCode(), 0);
    EXPECT_TRUE(stationLine24(sim.tcpPort()).contains(": speed 0,"))
        << "the station ends with the phone's loco standing: " << stationLine24(sim.tcpPort()).toStdString();
}

} // namespace
} // namespace stellwerk::cli
