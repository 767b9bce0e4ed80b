// The real stellwerk-sim with --ms1 N: the option is listed and checked, and its handhelds log in over the
// station's TCP port to a master on the network side (the test's), each with its own UID, name and node.

#include "SimProgram.h"

#include "Ms1TestSupport.h"
#include "TestMaster.h"
#include "transport/FrameAssembler.h"
#include "transport/NetworkFraming.h"

#include <QTcpSocket>

namespace stellwerk::sim::test {
namespace {

using support::Quiet;
using support::SimProgram;

TEST(SimProgram, HelpListsTheMs1Option) {
    SimProgram sim({"--help"});
    EXPECT_EQ(sim.exitCode(), 0);
    EXPECT_TRUE(sim.output().contains("--ms1 <N>")) << sim.output().toStdString();
    EXPECT_TRUE(sim.output().contains("--no-handheld-master")) << sim.output().toStdString();
}

TEST(SimProgram, MoreHandheldsThanLoginsAtOnceAreRefused) {
    SimProgram sim({"--ms1", "32"});
    EXPECT_EQ(sim.exitCode(), 2);
    EXPECT_TRUE(sim.output().contains("--ms1: '32' is not 0..31")) << sim.output().toStdString();
}

// The handhelds start before anyone listens; they try again after the login wait (5 s), share the merged
// frames of their first three UID bytes, and the second retries once more after losing stage 3.
// Told not to be their master (as on a Gleisbox's bus), the station leaves them to a master over TCP.
TEST(SimProgram, TwoHandheldsLogInToAMasterOverTcp) {
    SimProgram sim(QStringList{"--ms1", "2", "--no-handheld-master"} + Quiet);
    const std::uint16_t port = sim.tcpPort();
    ASSERT_NE(port, 0) << sim.output().toStdString();
    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, port);
    ASSERT_TRUE(socket.waitForConnected(WaitMs));
    TestMaster master;
    transport::FrameAssembler assembler;
    QObject::connect(&socket, &QTcpSocket::readyRead, &socket, [&] {
        std::vector<CanFrame> frames;
        assembler.feed(transport::asBytes(socket.readAll()), frames);
        for (const CanFrame& f : frames)
            master.receive(f);
    });
    QObject::connect(&master, &TestMaster::framesEmitted, &socket, [&](const std::vector<CanFrame>& frames) {
        socket.write(transport::encodeFrames(frames));
    });

    EXPECT_TRUE(sim.printed("MS1 1: logged in as node 43")) << sim.output().toStdString();
    EXPECT_TRUE(sim.printed("MS1 1: drives 003 131-0")) << sim.output().toStdString();
    EXPECT_TRUE(sim.printed("MS1 2: logged in as node 45")) << sim.output().toStdString();
    EXPECT_EQ(master.nodeOf(0x000204B3), 43);
    EXPECT_EQ(master.nodeOf(0x000204B4), 45);
}

// By default the simulated CS2 is their master, as a real one is: they log in to it with nobody connected.
TEST(SimProgram, TwoHandheldsLogInToTheStationItself) {
    SimProgram sim(QStringList{"--ms1", "2"} + Quiet);
    ASSERT_NE(sim.tcpPort(), 0) << sim.output().toStdString();
    EXPECT_TRUE(sim.printed("MS1 1: logged in as node 43")) << sim.output().toStdString();
    EXPECT_TRUE(sim.printed("MS1 2: logged in as node 45")) << sim.output().toStdString();
    EXPECT_TRUE(sim.printed("MS1 1: drives ")) << sim.output().toStdString();
}

} // namespace
} // namespace stellwerk::sim::test
