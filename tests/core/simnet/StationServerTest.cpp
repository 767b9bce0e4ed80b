// The simulated CS2's network side: TCP clients and the UDP reply address see every frame the station
// emits; frames from one listener reach the station and the other listeners.

#include "sim/StationServer.h"

#include "SimTestSupport.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/TrainMovement.h"
#include "transport/FrameAssembler.h"
#include "transport/NetworkFraming.h"

#include <QNetworkDatagram>
#include <QTcpSocket>
#include <QUdpSocket>
#include <algorithm>
#include <gtest/gtest.h>
#include <memory>
#include <vector>

namespace stellwerk::sim {
namespace {

using can::CanFrame;

constexpr std::uint32_t Br218 = 0x4001;

// A TCP client of the simulated station, collecting the frames it receives.
class Client {
public:
    explicit Client(std::uint16_t port) {
        socket_.connectToHost(QHostAddress::LocalHost, port);
        QObject::connect(&socket_, &QTcpSocket::readyRead, &socket_,
                         [this] { assembler_.feed(transport::asBytes(socket_.readAll()), frames); });
    }

    bool connected() {
        return socket_.state() == QAbstractSocket::ConnectedState || socket_.waitForConnected(WaitMs);
    }
    void send(const QByteArray& bytes) {
        socket_.write(bytes);
        socket_.flush();
    }
    bool received(const std::function<bool(const CanFrame&)>& match) const {
        return std::ranges::any_of(frames, match);
    }

    std::vector<CanFrame> frames;

private:
    static constexpr int WaitMs = test::WaitMs;
    QTcpSocket socket_;
    transport::FrameAssembler assembler_;
};

// A station answering on loopback ports picked by the system; UDP replies go to `udpPeer_`.
class StationServerTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(udpPeer_.bind(QHostAddress::LocalHost, 0));
        StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.udpPort = 0;
        settings.tcpPort = 0;
        settings.udpReplyHost = QHostAddress::LocalHost;
        settings.udpReplyPort = udpPeer_.localPort();
        server_ = std::make_unique<StationServer>(station_, settings);
        ASSERT_TRUE(server_->listen()) << server_->errorString().toStdString();
        QObject::connect(&udpPeer_, &QUdpSocket::readyRead, &udpPeer_, [this] { readUdpPeer(); });
    }

    void readUdpPeer() {
        while (udpPeer_.hasPendingDatagrams()) {
            const QByteArray datagram = udpPeer_.receiveDatagram().data();
            udpDatagramSizes_.push_back(datagram.size());
            transport::decodeDatagram(transport::asBytes(datagram), udpFrames_);
        }
    }

    std::unique_ptr<Client> connectClient() {
        auto client = std::make_unique<Client>(server_->tcpPort());
        EXPECT_TRUE(client->connected());
        return client;
    }

    bool sendUdp(const QByteArray& datagram) {
        QUdpSocket sender;
        return sender.writeDatagram(datagram, QHostAddress::LocalHost, server_->udpPort()) == datagram.size();
    }

    SimulatedStation station_{StationLayout::demo(), {.power = SimulatedStation::Power::Running}};
    QUdpSocket udpPeer_;
    std::vector<CanFrame> udpFrames_;
    std::vector<qsizetype> udpDatagramSizes_;
    std::unique_ptr<StationServer> server_;
};

bool isPingAnswer(const CanFrame& frame) {
    return cs2::command(frame) == 0x18 && cs2::isResponse(frame);
}

TEST_F(StationServerTest, ListensOnThePortsItWasGiven) {
    EXPECT_NE(server_->tcpPort(), 0);
    EXPECT_NE(server_->udpPort(), 0);
    EXPECT_EQ(server_->listeners().size(), 2);
}

TEST_F(StationServerTest, FrameFromOneTcpClientReachesTheStationAndItsAnswerReachesBoth) {
    auto first = connectClient();
    auto second = connectClient();
    ASSERT_TRUE(test::waitFor([&] { return server_->tcpClientCount() == 2; }));
    first->send(transport::encodeFrames(std::vector{test::speed(Br218, 400)}));
    ASSERT_TRUE(test::waitFor([&] { return station_.loco(Br218) && station_.loco(Br218)->speed == 400; }));

    first->send(transport::encodeFrames(std::vector{test::ping()}));
    EXPECT_TRUE(
        test::waitFor([&] { return first->received(isPingAnswer) && second->received(isPingAnswer); }));
    // The gateway puts a client's frame on the bus: the other client sees it, the sender does not get it
    // back.
    EXPECT_TRUE(second->received([](const CanFrame& f) { return f == test::ping(); }));
    EXPECT_FALSE(first->received([](const CanFrame& f) { return f == test::ping(); }));
}

TEST_F(StationServerTest, FramesSplitAcrossTcpSegmentsAreReassembled) {
    auto client = connectClient();
    const QByteArray bytes = transport::encodeFrames(std::vector{test::speed(Br218, 250), test::ping()});
    for (qsizetype start = 0; start < bytes.size(); start += 5) { // 26 bytes in pieces of 5
        client->send(bytes.mid(start, 5));
        QTest::qWait(5);
    }
    EXPECT_TRUE(test::waitFor([&] { return client->received(isPingAnswer); }));
    ASSERT_NE(station_.loco(Br218), nullptr);
    EXPECT_EQ(station_.loco(Br218)->speed, 250);
    EXPECT_EQ(server_->counters().framesIn, 2U);
}

TEST_F(StationServerTest, TcpFrameWithDlcAboveEightIsCountedAndDropped) {
    auto client = connectClient();
    QByteArray broken = transport::encodeFrames(std::vector{test::ping()});
    broken[4] = 9;
    client->send(broken + transport::encodeFrames(std::vector{test::ping()}));
    EXPECT_TRUE(test::waitFor([&] { return server_->counters().framesIn == 1; }));
    EXPECT_EQ(server_->counters().malformedFrames, 1U);
}

TEST_F(StationServerTest, UdpDatagramOfSeveralFramesIsAcceptedAndAnsweredOnePerDatagram) {
    ASSERT_TRUE(sendUdp(transport::encodeFrames(std::vector{test::speed(Br218, 700), test::ping()})));
    EXPECT_TRUE(test::waitFor([&] { return std::ranges::any_of(udpFrames_, isPingAnswer); }));
    ASSERT_NE(station_.loco(Br218), nullptr);
    EXPECT_EQ(station_.loco(Br218)->speed, 700);
    EXPECT_TRUE(std::ranges::all_of(udpDatagramSizes_, [](qsizetype size) { return size == 13; }));
    // A frame that came in by UDP is not sent back to the UDP peer.
    EXPECT_FALSE(std::ranges::any_of(udpFrames_, [](const CanFrame& f) { return f == test::ping(); }));
}

TEST_F(StationServerTest, UdpDatagramThatIsNotWholeFramesIsCountedAndDropped) {
    ASSERT_TRUE(sendUdp(QByteArray("garbage, not a CAN frame")));
    ASSERT_TRUE(sendUdp(transport::encodeFrames(std::vector{test::ping()})));
    EXPECT_TRUE(test::waitFor([&] { return server_->counters().framesIn == 1; }));
    EXPECT_EQ(server_->counters().malformedDatagrams, 1U);
}

TEST_F(StationServerTest, FrameFromUdpIsForwardedToTcpClients) {
    auto client = connectClient();
    ASSERT_TRUE(test::waitFor([&] { return server_->tcpClientCount() == 1; }));
    ASSERT_TRUE(sendUdp(transport::encodeFrames(std::vector{test::ping()})));
    EXPECT_TRUE(test::waitFor([&] {
        return client->received([](const CanFrame& f) { return f == test::ping(); }) &&
               client->received(isPingAnswer);
    }));
}

TEST_F(StationServerTest, FramesTheStationEmitsOnItsOwnReachEveryListener) {
    auto first = connectClient();
    auto second = connectClient();
    ASSERT_TRUE(test::waitFor([&] { return server_->tcpClientCount() == 2; }));
    station_.setContact(0, 42, true); // as the train movement does
    const auto isEvent = [](const CanFrame& f) { return cs2::command(f) == 0x11 && f.data[3] == 42; };
    EXPECT_TRUE(test::waitFor([&] {
        return first->received(isEvent) && second->received(isEvent) &&
               std::ranges::any_of(udpFrames_, isEvent);
    }));
}

TEST_F(StationServerTest, TrainStartedByATcpClientReportsItsContactsToEveryListener) {
    using namespace std::chrono_literals;
    // On Gleis 1 (contact 1), facing Ausfahrt Ost (contact 8) 900 mm ahead: 1.8 s at full speed.
    TrainMovement trains(station_, {{Br218, 1, trackgraph::End::B}}, {.tick = 20ms});
    trains.start();
    auto driver = connectClient();
    auto watcher = connectClient();
    ASSERT_TRUE(test::waitFor([&] { return server_->tcpClientCount() == 2; }));
    driver->send(transport::encodeFrames(std::vector{test::speed(Br218, 1000)}));
    // Ausfahrt Ost (contact 8) occupied: the S88 event, with old and new state, as a Link-S88 sends it.
    const auto occupiedAusfahrtOst = [](const CanFrame& f) {
        return cs2::command(f) == 0x11 && cs2::isResponse(f) && f.dlc == 8 && f.data[3] == 8 &&
               f.data[4] == 0 && f.data[5] == 1;
    };
    EXPECT_TRUE(test::waitFor(
        [&] {
            return driver->received(occupiedAusfahrtOst) && watcher->received(occupiedAusfahrtOst) &&
                   std::ranges::any_of(udpFrames_, occupiedAusfahrtOst);
        },
        4 * test::WaitMs));
}

TEST_F(StationServerTest, ClosedClientIsForgotten) {
    {
        auto client = connectClient();
        ASSERT_TRUE(test::waitFor([&] { return server_->tcpClientCount() == 1; }));
    }
    EXPECT_TRUE(test::waitFor([&] { return server_->tcpClientCount() == 0; }));
    station_.setContact(0, 7, true); // nobody left to write to
    EXPECT_EQ(server_->counters().tcpConnections, 1U);
}

TEST_F(StationServerTest, SecondServerOnTheSamePortReportsWhy) {
    StationServerSettings settings;
    settings.listenAddress = QHostAddress::LocalHost;
    settings.udp = false;
    settings.tcpPort = server_->tcpPort();
    StationServer second(station_, settings);
    EXPECT_FALSE(second.listen());
    EXPECT_TRUE(second.errorString().startsWith("TCP port"));
}

} // namespace
} // namespace stellwerk::sim
