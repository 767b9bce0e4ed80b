// The real stellwerk-sim's trains as another program sees them: --place checked and listed, every accident a
// line on standard output beginning with "accident:", and the counts as JSON on its web server
// (GET /accidents), on the demo and on a layout folder of the corpus (--layout).

#include "SimProgram.h"
#include "SimTestSupport.h"
#include "transport/NetworkFraming.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTcpServer>
#include <QTcpSocket>
#include <gtest/gtest.h>
#include <vector>

namespace stellwerk::sim {
namespace {

using support::SimProgram;

constexpr int WaitMs = 15000;

std::uint16_t freePort() {
    QTcpServer server;
    server.listen(QHostAddress::LocalHost, 0);
    return server.serverPort();
}

// On loopback ports, with trains and the web server on `httpPort`.
QStringList withTrains(std::uint16_t httpPort) {
    return {"--listen",  "127.0.0.1",  "--udp-port", "0",           "--udp-reply-host",
            "127.0.0.1", "--tcp-port", "0",          "--http-port", QString::number(httpPort),
            "--tick",    "20"};
}

// What a controller on the station's TCP port does: Go, and locomotives at full speed.
bool driveAtFullSpeed(std::uint16_t tcpPort, const std::vector<std::uint32_t>& locIds) {
    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, tcpPort);
    if (!socket.waitForConnected(WaitMs))
        return false;
    std::vector<can::CanFrame> frames{test::command(cs2::SystemGo{})};
    for (const std::uint32_t locId : locIds)
        frames.push_back(test::speed(locId, 1000));
    socket.write(transport::encodeFrames(frames));
    return socket.waitForBytesWritten(WaitMs);
}

QJsonObject accidentsOn(std::uint16_t httpPort) {
    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, httpPort);
    if (!socket.waitForConnected(WaitMs))
        return {};
    socket.write("GET /accidents HTTP/1.0\r\n\r\n");
    QByteArray response;
    while (socket.state() == QAbstractSocket::ConnectedState && socket.waitForReadyRead(WaitMs))
        response += socket.readAll();
    response += socket.readAll();
    return QJsonDocument::fromJson(response.mid(response.indexOf("\r\n\r\n") + 4)).object();
}

TEST(SimProgramTrains, HelpListsPlaceAndBadPlacesAreRefused) {
    SimProgram help({"--help"});
    EXPECT_EQ(help.exitCode(), 0);
    EXPECT_TRUE(help.output().contains("--place <LOC=CONTACT[:END]>")) << help.output().toStdString();
    const std::pair<QStringList, QString> refused[] = {
        {{"--place", "mfx:1"}, "--place: 'mfx:1' is not LOC=CONTACT[:END] (e.g. mfx:5=12:a)"},
        {{"--place", "mfx:1=3:x"}, "--place: the end 'x' is not a or b"},
        {{"--place", "mfx:1=3", "--no-trains"},
         "--place puts trains on the track, --no-trains keeps them off: choose one"},
    };
    for (const auto& [arguments, message] : refused) {
        SimProgram program(arguments);
        EXPECT_EQ(program.exitCode(), 2) << arguments.join(' ').toStdString();
        EXPECT_TRUE(program.output().contains(message)) << program.output().toStdString();
    }
    SimProgram nowhere(withTrains(0) + QStringList{"--place", "mfx:1=99"});
    EXPECT_EQ(nowhere.exitCode(), 1);
    EXPECT_TRUE(nowhere.output().contains("stellwerk-sim: --place: mfx:1: no block of the track plan holds "
                                          "contact 99"))
        << nowhere.output().toStdString();
}

// On the demo: the ICE from Block 1 into Ausfahrt Ost, where the V 100 stands (collision), and the BR 218
// from the Abstellgleis into the Bw's buffer stop.
TEST(SimProgramTrains, CollisionAndBufferStopArePrintedAndCounted) {
    const std::uint16_t http = freePort();
    SimProgram sim(withTrains(http) +
                   QStringList{"--place", "mfx:1=9", "--place", "mfx:2=3:a", "--place", "mm2:24=8"});
    const std::uint16_t tcp = sim.tcpPort();
    ASSERT_NE(tcp, 0) << sim.output().toStdString();
    EXPECT_TRUE(sim.printed("trains: 3 on 9 blocks"));
    EXPECT_EQ(accidentsOn(http)["total"].toInt(-1), 0);
    ASSERT_TRUE(driveAtFullSpeed(tcp, {0x4001, 0x4002}));
    EXPECT_TRUE(sim.printed("accident: collision: ICE 3 Velaro and V 100 2023 in block \"Ausfahrt Ost\"\n"))
        << sim.output().toStdString();
    EXPECT_TRUE(sim.printed("accident: buffer stop: BR 218 Ost ran into the buffer stop beyond block "
                            "\"Abstellgleis\" (page 'Bw', column 10, row 2)\n"))
        << sim.output().toStdString();
    const QJsonObject counts = accidentsOn(http);
    EXPECT_EQ(counts["collisions"].toInt(), 1);
    EXPECT_EQ(counts["bufferStops"].toInt(), 1);
    EXPECT_EQ(counts["turnoutsRunThrough"].toInt(), 0);
    EXPECT_EQ(counts["total"].toInt(), 2);
    EXPECT_EQ(counts["accidents"].toArray().size(), 2);
}

// karben.cs2 of the corpus: 602's train runs west through turnout 2 ("24"), which lies straight, against it.
TEST(SimProgramTrains, ATurnoutRunThroughOnACorpusLayoutIsPrintedAndCounted) {
    const std::uint16_t http = freePort();
    SimProgram sim(withTrains(http) + QStringList{"--layout",
                                                  QStringLiteral(STELLWERK_SHARED_DIR) +
                                                      "/corpus/GBert__railroad/can2udp/files/maerklin/config",
                                                  "--place", "mm2:11=102:a"});
    const std::uint16_t tcp = sim.tcpPort();
    ASSERT_NE(tcp, 0) << sim.output().toStdString();
    ASSERT_TRUE(driveAtFullSpeed(tcp, {0x000b}));
    EXPECT_TRUE(sim.printed("accident: turnout run through: 111 043-6 ran through turnout 2 set against it"))
        << sim.output().toStdString();
    EXPECT_EQ(accidentsOn(http)["turnoutsRunThrough"].toInt(), 1);
}

} // namespace
} // namespace stellwerk::sim
