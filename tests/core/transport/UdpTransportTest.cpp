// UDP (field notes, "Framing"): one 13-byte frame per datagram out; datagrams of n x 13 bytes in; anything
// else counted and dropped. Only 127.0.0.1 and ports the system chose.

#include "transport/UdpTransport.h"

#include "TestSupport.h"
#include "transport/NetworkFraming.h"

#include <QNetworkDatagram>
#include <QUdpSocket>

namespace stellwerk::transport::test {
namespace {

using State = Transport::State;

// The station's side: a socket on 127.0.0.1 that the transport sends to, and that sends to the transport.
class UdpTransportTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(station.bind(QHostAddress::LocalHost, 0));
        settings.host = QStringLiteral("127.0.0.1");
        settings.remotePort = station.localPort();
        settings.localPort = 0;
        settings.localAddress = QHostAddress::LocalHost;
        settings.reconnect = fastReconnect();
    }

    void openTransport() {
        transport = std::make_unique<UdpTransport>(settings);
        recorder = std::make_unique<Recorder>(*transport);
        transport->open();
        ASSERT_TRUE(waitForState(*transport, State::Connected));
    }

    void sendToTransport(const QByteArray& datagram) {
        ASSERT_EQ(station.writeDatagram(datagram, QHostAddress::LocalHost, transport->boundPort()),
                  datagram.size());
    }

    std::vector<QByteArray> datagramsAtStation(std::size_t count) {
        std::vector<QByteArray> datagrams;
        waitFor([&] {
            while (station.hasPendingDatagrams())
                datagrams.push_back(station.receiveDatagram().data());
            return datagrams.size() >= count;
        });
        return datagrams;
    }

    QUdpSocket station;
    UdpSettings settings;
    std::unique_ptr<UdpTransport> transport;
    std::unique_ptr<Recorder> recorder;
};

TEST_F(UdpTransportTest, ConnectedOnceBound) {
    openTransport();
    EXPECT_NE(transport->boundPort(), 0);
    EXPECT_EQ(transport->description(),
              QStringLiteral("udp://127.0.0.1:%1?listen=0").arg(settings.remotePort));
}

TEST_F(UdpTransportTest, DatagramOfThreeFramesArrivesAsOneBatch) {
    openTransport();
    sendToTransport(encodeFrames(numberedFrames(3)));
    ASSERT_TRUE(recorder->waitForFrames(3));
    EXPECT_EQ(recorder->batches.size(), 1u);
    EXPECT_EQ(recorder->frames(), numberedFrames(3));
    EXPECT_EQ(transport->counters().framesIn, 3u);
}

TEST_F(UdpTransportTest, SingleFrameDatagramsArriveInOrder) {
    openTransport();
    for (const CanFrame& frame : numberedFrames(20))
        sendToTransport(encodeFrames(std::vector{frame}));
    ASSERT_TRUE(recorder->waitForFrames(20));
    EXPECT_EQ(recorder->frames(), numberedFrames(20));
}

TEST_F(UdpTransportTest, StandardFrameIsRefusedWithAClearProblem) {
    openTransport();
    const std::uint8_t payload[] = {1, 2};
    EXPECT_FALSE(transport->send(can::CanFrame::standard(0x7FF, payload)));
    EXPECT_TRUE(transport->send(numbered(1)));
    const auto datagrams = datagramsAtStation(1);
    ASSERT_EQ(datagrams.size(), 1u);
    EXPECT_EQ(datagrams[0], encodeFrames(numberedFrames(1, 1))) << "only the extended frame went out";
    EXPECT_EQ(transport->counters().dropped, 1u);
    ASSERT_EQ(recorder->problems.size(), 1u);
    EXPECT_TRUE(recorder->problems[0].contains(QLatin1String("id 0x7ff")))
        << recorder->problems[0].toStdString();
}

TEST_F(UdpTransportTest, EachSentFrameIsOneDatagramOf13Bytes) {
    openTransport();
    EXPECT_EQ(transport->sendBatch(numberedFrames(3)), 3u);
    const auto datagrams = datagramsAtStation(3);
    ASSERT_EQ(datagrams.size(), 3u);
    for (std::size_t i = 0; i < datagrams.size(); ++i)
        EXPECT_EQ(datagrams[i], encodeFrames(std::vector{numbered(std::uint16_t(i))}));
    EXPECT_EQ(transport->counters().framesOut, 3u);
}

TEST_F(UdpTransportTest, GarbageDatagramsAreCountedAndIgnored) {
    openTransport();
    sendToTransport(QByteArray(7, 'x'));
    sendToTransport(QByteArray(14, '\0'));
    sendToTransport(QByteArray());
    sendToTransport(encodeFrames(numberedFrames(1)));
    ASSERT_TRUE(recorder->waitForFrames(1));
    EXPECT_EQ(recorder->frames(), numberedFrames(1));
    EXPECT_EQ(transport->counters().malformed, 3u);
    EXPECT_EQ(transport->counters().framesIn, 1u);
}

TEST_F(UdpTransportTest, FrameWithDlcAboveEightIsCountedMalformed) {
    openTransport();
    QByteArray datagram = encodeFrames(numberedFrames(2));
    datagram[4] = char(9);
    sendToTransport(datagram);
    ASSERT_TRUE(recorder->waitForFrames(1));
    EXPECT_EQ(recorder->frames(), std::vector{numbered(1)});
    EXPECT_EQ(transport->counters().malformed, 1u);
}

// A CS2 is often reached by broadcast. 127.255.255.255 is the loopback network's broadcast address: the
// system refuses to send there unless the socket allows broadcasts.
TEST_F(UdpTransportTest, FramesMayBeBroadcast) {
    QUdpSocket listener;
    ASSERT_TRUE(listener.bind(QHostAddress(QStringLiteral("127.255.255.255")), 0));
    settings.host = QStringLiteral("127.255.255.255");
    settings.remotePort = listener.localPort();
    openTransport();
    EXPECT_TRUE(transport->send(numbered(2)));
    ASSERT_TRUE(waitFor([&] { return listener.hasPendingDatagrams(); }));
    EXPECT_EQ(listener.receiveDatagram().data(), encodeFrames(std::vector{numbered(2)}));
    EXPECT_EQ(transport->counters().framesOut, 1u);
    EXPECT_TRUE(recorder->problems.empty());
}

TEST_F(UdpTransportTest, SendBeforeOpenIsRefusedAndCounted) {
    UdpTransport closed(settings);
    EXPECT_FALSE(closed.send(numbered(1)));
    EXPECT_EQ(closed.counters().dropped, 1u);
}

TEST_F(UdpTransportTest, HostNameIsLookedUp) {
    settings.host = QStringLiteral("localhost");
    openTransport();
    EXPECT_TRUE(transport->send(numbered(4)));
    const auto datagrams = datagramsAtStation(1);
    ASSERT_EQ(datagrams.size(), 1u);
    EXPECT_EQ(datagrams[0], encodeFrames(std::vector{numbered(4)}));
}

// Another program holds the receive port without sharing it: reported, retried, taken when it is free.
TEST_F(UdpTransportTest, BusyReceivePortIsReportedAndRetried) {
    auto holder = std::make_unique<QUdpSocket>();
    ASSERT_TRUE(holder->bind(QHostAddress::LocalHost, 0, QAbstractSocket::DontShareAddress));
    settings.localPort = holder->localPort();
    transport = std::make_unique<UdpTransport>(settings);
    recorder = std::make_unique<Recorder>(*transport);
    transport->open();
    ASSERT_TRUE(waitFor([&] { return !recorder->problems.empty(); }));
    EXPECT_EQ(transport->state(), State::Reconnecting);
    EXPECT_TRUE(recorder->problems[0].contains(QString::number(settings.localPort)))
        << recorder->problems[0].toStdString();
    EXPECT_TRUE(transport->send(numbered(1))) << "frames wait while the port is busy";
    holder.reset();
    ASSERT_TRUE(waitForState(*transport, State::Connected));
    const auto datagrams = datagramsAtStation(1);
    ASSERT_EQ(datagrams.size(), 1u);
    EXPECT_EQ(transport->boundPort(), settings.localPort);
}

} // namespace
} // namespace stellwerk::transport::test
