// Several devices on one simulated CAN bus: every frame a peer sends reaches every other peer and the
// outside (the station server's listeners), never its sender; a round goes by CAN arbitration; identical
// frames of two peers pass as one. The simulated CS2 behind its server on such a bus.

#include "sim/SimulatedBus.h"

#include "RecordingPeer.h"
#include "SimTestSupport.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "transport/FrameAssembler.h"
#include "transport/NetworkFraming.h"

#include <QTcpSocket>
#include <algorithm>
#include <gtest/gtest.h>
#include <memory>
#include <vector>

namespace stellwerk::sim::test {
namespace {

using can::CanFrame;

CanFrame frame(std::uint32_t id, std::uint8_t byte) {
    return CanFrame::extendedFrame(id, std::vector<std::uint8_t>{byte});
}

const CanFrame Low = frame(0x10000001, 1);
const CanFrame Middle = frame(0x10000002, 2);
const CanFrame High = frame(0x10000003, 3);

class SimulatedBusTest : public ::testing::Test {
protected:
    void SetUp() override {
        for (RecordingPeer* peer : {&a_, &b_, &c_})
            bus_.attach(*peer);
        QObject::connect(&bus_, &SimulatedBus::framesCarried, &bus_,
                         [this](const std::vector<CanFrame>& frames) {
                             outside_.insert(outside_.end(), frames.begin(), frames.end());
                         });
    }

    SimulatedBus bus_;
    RecordingPeer a_, b_, c_;
    std::vector<CanFrame> outside_;
};

TEST_F(SimulatedBusTest, AFrameReachesEveryOtherPeerAndTheOutsideNeverItsSender) {
    a_.send({Low});
    ASSERT_TRUE(waitFor([this] { return !c_.received.empty(); }));
    EXPECT_EQ(b_.received, std::vector{Low});
    EXPECT_EQ(c_.received, std::vector{Low});
    EXPECT_TRUE(a_.received.empty());
    EXPECT_EQ(outside_, std::vector{Low});
}

TEST_F(SimulatedBusTest, AFrameFromOutsideReachesEveryPeerAndIsNotCarriedBackOut) {
    bus_.putFromOutside({Middle});
    ASSERT_TRUE(waitFor([this] { return !c_.received.empty(); }));
    EXPECT_EQ(a_.received, std::vector{Middle});
    EXPECT_EQ(b_.received, std::vector{Middle});
    EXPECT_TRUE(outside_.empty());
}

// As CAN arbitration: the lowest identifier among the senders' next frames first, each sender in order.
TEST_F(SimulatedBusTest, ARoundGoesByArbitrationAndKeepsEachSendersOrder) {
    a_.send({High, Low});
    b_.send({Middle});
    ASSERT_TRUE(waitFor([this] { return c_.received.size() == 3; }));
    EXPECT_EQ(c_.received, (std::vector{Middle, High, Low}));
    EXPECT_EQ(outside_, c_.received);
}

TEST_F(SimulatedBusTest, IdenticalFramesOfTwoPeersInOneRoundPassAsOne) {
    a_.send({Low, Low});
    b_.send({Low});
    ASSERT_TRUE(waitFor([this] { return c_.received.size() >= 2; }));
    QTest::qWait(20);
    EXPECT_EQ(c_.received, (std::vector{Low, Low})) << "a's two frames; b's is one of them";
    EXPECT_EQ(a_.received, std::vector<CanFrame>{}) << "nobody else sent it";
    EXPECT_EQ(b_.received, std::vector{Low}) << "a's second frame";
}

TEST_F(SimulatedBusTest, AnAnswerGoesInTheNextRound) {
    a_.send({Low});
    ASSERT_TRUE(waitFor([this] { return !b_.received.empty(); }));
    b_.send({High});
    ASSERT_TRUE(waitFor([this] { return !a_.received.empty(); }));
    EXPECT_EQ(a_.received, std::vector{High});
    EXPECT_EQ(outside_, (std::vector{Low, High}));
}

TEST_F(SimulatedBusTest, APeerThatIsDestroyedLeavesTheBus) {
    auto leaving = std::make_unique<RecordingPeer>();
    bus_.attach(*leaving);
    EXPECT_EQ(bus_.peerCount(), 4u);
    leaving.reset();
    EXPECT_EQ(bus_.peerCount(), 3u);
    a_.send({Low});
    EXPECT_TRUE(waitFor([this] { return !c_.received.empty(); }));
}

// A TCP client of the simulated CS2, collecting what it receives.
bool isBusPingAnswer(const CanFrame& f) {
    return cs2::command(f) == 0x18 && cs2::isResponse(f);
}

class TcpClient {
public:
    explicit TcpClient(std::uint16_t port) {
        socket_.connectToHost(QHostAddress::LocalHost, port);
        QObject::connect(&socket_, &QTcpSocket::readyRead, &socket_,
                         [this] { assembler_.feed(transport::asBytes(socket_.readAll()), frames); });
    }
    bool connected() { return socket_.waitForConnected(WaitMs); }
    void send(const std::vector<CanFrame>& sent) {
        socket_.write(transport::encodeFrames(sent));
        socket_.flush();
    }
    std::vector<CanFrame> frames;

private:
    QTcpSocket socket_;
    transport::FrameAssembler assembler_;
};

// The listeners are the bus's outside: they see what every peer sends, and what they send reaches every
// peer; the station answers them as before.
TEST(StationServerOnABus, ClientsSeeEveryPeerAndReachEveryPeer) {
    SimulatedBus bus;
    SimulatedStation station(StationLayout::demo());
    RecordingPeer handheld;
    bus.attach(station);
    bus.attach(handheld);
    StationServerSettings settings;
    settings.listenAddress = QHostAddress::LocalHost;
    settings.udp = false;
    settings.tcpPort = 0;
    StationServer server(station, bus, settings);
    ASSERT_TRUE(server.listen()) << server.errorString().toStdString();
    TcpClient client(server.tcpPort());
    ASSERT_TRUE(client.connected());
    ASSERT_TRUE(waitFor([&] { return server.tcpClientCount() == 1; }));

    handheld.send({Low});
    ASSERT_TRUE(waitFor([&] { return client.frames.size() == 1; }));
    EXPECT_EQ(client.frames[0], Low);
    client.send({ping()});
    ASSERT_TRUE(waitFor([&] { return std::ranges::any_of(client.frames, isBusPingAnswer); }));
    EXPECT_EQ(handheld.received.size(), 2u) << "the client's ping and the station's answer";
    EXPECT_EQ(handheld.received.at(0), ping());
    EXPECT_EQ(server.counters().framesIn, 1u);
    EXPECT_EQ(server.counters().framesOut, 2u) << "the peer's frame and the station's answer";
}

} // namespace
} // namespace stellwerk::sim::test
