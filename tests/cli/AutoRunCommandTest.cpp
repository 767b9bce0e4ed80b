// `stellwerk-cli --station URL auto run` against the real stellwerk-sim, as a user runs them: both told the
// same
// --place, the CLI drives the trains automatically for a few seconds, prints its events as JSON lines and a
// summary, and the simulator's referee (GET /accidents) counts no accident.

#include "CliApplication.h"
#include "SimProgram.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace stellwerk::cli {
namespace {

std::uint16_t freePort() {
    QTcpServer server;
    server.listen(QHostAddress::LocalHost, 0);
    return server.serverPort();
}

QJsonObject accidentsOn(std::uint16_t httpPort) {
    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, httpPort);
    if (!socket.waitForConnected(5000))
        return {};
    socket.write("GET /accidents HTTP/1.0\r\n\r\n");
    QByteArray response;
    while (socket.state() == QAbstractSocket::ConnectedState && socket.waitForReadyRead(5000))
        response += socket.readAll();
    response += socket.readAll();
    return QJsonDocument::fromJson(response.mid(response.indexOf("\r\n\r\n") + 4)).object();
}

const QStringList DemoTrains{"--place", "mfx:1=1", "--place", "mfx:2=4", "--place", "mm2:24=2"};

TEST(AutoRunCommand, ThreeTrainsRunOnTheDemoWithoutAccidentAndASummaryEndsTheRun) {
    test::ensureApplication();
    const std::uint16_t http = freePort();
    support::SimProgram sim(QStringList{"--listen", "127.0.0.1", "--udp-port", "0", "--udp-reply-host",
                                        "127.0.0.1", "--tcp-port", "0", "--http-port", QString::number(http),
                                        "--tick", "20"} +
                            DemoTrains);
    const std::uint16_t port = sim.tcpPort();
    ASSERT_NE(port, 0) << sim.output().toStdString();
    QProcess cli;
    cli.start(STELLWERK_CLI,
              QStringList{"--station", QStringLiteral("tcp://127.0.0.1:%1").arg(port), "auto", "run"} +
                  DemoTrains + QStringList{"--seconds", "15", "--json"});
    support::runEventsUntil([&] { return cli.state() == QProcess::NotRunning; }, 40000);
    const QString out = QString::fromUtf8(cli.readAllStandardOutput());
    EXPECT_EQ(cli.exitCode(), 0) << out.toStdString() << cli.readAllStandardError().toStdString();
    const QStringList lines = out.trimmed().split('\n');
    ASSERT_FALSE(lines.isEmpty());
    EXPECT_EQ(lines.first(),
              R"({"block":4,"blockName":"Gleis 1","event":"placed","loc":"0x4001",)"
              R"("text":"BR 218 Ost placed in \"Gleis 1\" facing end b","train":"BR 218 Ost"})");
    for (const char* kind :
         {"\"reserved\"", "\"turnout-set\"", "\"departed\"", "\"entered\"", "\"released\""})
        EXPECT_TRUE(out.contains(QLatin1String(kind))) << kind << "\n" << out.toStdString();
    const QJsonObject summary = QJsonDocument::fromJson(lines.last().toUtf8()).object();
    EXPECT_EQ(summary["event"].toString(), "summary");
    EXPECT_EQ(summary["faults"].toInt(-1), 0);
    EXPECT_GE(summary["blockMoves"].toInt(), 3);
    EXPECT_EQ(summary["trains"].toArray().size(), 3);
    const QJsonObject accidents = accidentsOn(http);
    EXPECT_EQ(accidents["total"].toInt(-1), 0) << sim.output().toStdString();
    for (const QJsonValue train : summary["trains"].toArray())
        EXPECT_EQ(train["state"].toString(), "stopped");
}

// --schedule: the BR 218 runs from Gleis 1 to its one stop, Ausfahrt Ost, and stays; the file then says it
// has run its schedule (next 1 of 1), so a run started again does not send it anywhere.
TEST(AutoRunCommand, AScheduleFileSendsTheTrainToItsStopAndRecordsWhereItIs) {
    test::ensureApplication();
    QTemporaryDir folder;
    const QString path = folder.filePath("schedules.json");
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"trains": [{"loc": "mfx:1", "stops": [{"block": "Ausfahrt Ost", "dwell": 1}]}]})");
    file.close();
    support::SimProgram sim(QStringList{"--listen", "127.0.0.1", "--udp-port", "0", "--udp-reply-host",
                                        "127.0.0.1", "--tcp-port", "0", "--http-port", "0", "--tick", "20",
                                        "--place", "mfx:1=1"});
    ASSERT_NE(sim.tcpPort(), 0) << sim.output().toStdString();
    QProcess cli;
    cli.start(STELLWERK_CLI,
              QStringList{"--station", QStringLiteral("tcp://127.0.0.1:%1").arg(sim.tcpPort()), "auto", "run",
                          "--place", "mfx:1=1", "--schedule", path, "--seconds", "12"});
    support::runEventsUntil([&] { return cli.state() == QProcess::NotRunning; }, 30000);
    const std::string out = cli.readAllStandardOutput().toStdString();
    EXPECT_EQ(cli.exitCode(), 0) << out << cli.readAllStandardError().toStdString();
    EXPECT_NE(out.find("arrived in \"Ausfahrt Ost\", stop 1 of 1, for 1 s"), std::string::npos) << out;
    EXPECT_NE(out.find("has run its schedule"), std::string::npos) << out;
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QJsonObject train =
        QJsonDocument::fromJson(file.readAll()).object()["trains"].toArray()[0].toObject();
    EXPECT_EQ(train["loc"].toString(), "0x4001");
    EXPECT_EQ(train["next"].toInt(-1), 1);
    EXPECT_EQ(train["stops"].toArray()[0].toObject()["block"].toString(), "Ausfahrt Ost");
}

TEST(AutoRunCommand, APlacementTheCommandCannotReadIsAUsageError) {
    test::ensureApplication();
    QProcess cli;
    cli.start(STELLWERK_CLI, {"--station", "tcp://127.0.0.1:1", "auto", "run", "--place", "mfx:1=3:x"});
    support::runEventsUntil([&] { return cli.state() == QProcess::NotRunning; }, 10000);
    EXPECT_EQ(cli.exitCode(), 2);
    EXPECT_TRUE(cli.readAllStandardError().contains("auto run: --place: the end 'x' is not a or b"));
}

} // namespace
} // namespace stellwerk::cli
