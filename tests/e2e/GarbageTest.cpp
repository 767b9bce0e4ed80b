// Input that is not CS2 frames, on every socket of the conversation: datagrams that are not n x 13 bytes,
// frames with a DLC above 8, a connection that ends inside a frame, a frame no command has. Each is
// counted where it arrives and dropped, and the conversation goes on as if nothing had happened.

#include "E2eSupport.h"
#include "JunkRelay.h"
#include "cs2/Codec.h"
#include "transport/NetworkFraming.h"

#include <QTcpSocket>
#include <QUdpSocket>
#include <vector>

namespace stellwerk::e2e {
namespace {

using State = transport::Transport::State;

// Datagram sizes that are not a multiple of 13 bytes.
const std::vector<int> WrongSizes{1, 12, 14, 25, 27, 100};

QByteArray bytes(int size, char fill = '\x5A') {
    return QByteArray(size, fill);
}

// A frame in network form whose DLC byte says 9 (at most 8 is allowed).
QByteArray frameWithDlcNine() {
    QByteArray frame =
        transport::encodeFrames(std::vector{cs2::encode(command(cs2::LocoSpeed{cs2::LocId(MfxLoco), 100}))});
    frame[4] = 9;
    return frame;
}

// A speed command with three data bytes: no form of document 3.4 has that length.
can::CanFrame undecodableFrame() {
    can::CanFrame frame;
    frame.id = cs2::makeId(0, 0x04, false, 0x2F11);
    frame.dlc = 3;
    frame.data = {0x00, 0x00, 0x40};
    return frame;
}

bool sendDatagram(const QByteArray& datagram, std::uint16_t port) {
    QUdpSocket sender;
    return sender.writeDatagram(datagram, QHostAddress::LocalHost, port) == datagram.size();
}

bool speedAcknowledged(Rig& rig, std::uint16_t speed) {
    const bool acknowledged =
        rig.acknowledge(command(cs2::LocoSpeed{cs2::LocId(MfxLoco), speed})).succeeded();
    return acknowledged && rig.station.loco(MfxLoco)->speed == speed;
}

TEST(Garbage, UdpDatagramsOfWrongSizeToTheStationAreCountedAndIgnored) {
    Rig rig(Wire::Udp);
    ASSERT_TRUE(rig.start());
    const auto framesBefore = rig.server->counters().framesIn;
    for (int size : WrongSizes)
        ASSERT_TRUE(sendDatagram(bytes(size), rig.stationUdpPort()));
    ASSERT_TRUE(sendDatagram(frameWithDlcNine(), rig.stationUdpPort()));
    ASSERT_TRUE(waitFor([&] {
        return rig.server->counters().malformedDatagrams == WrongSizes.size() &&
               rig.server->counters().malformedFrames == 1;
    }));
    EXPECT_EQ(rig.server->counters().framesIn, framesBefore);
    EXPECT_TRUE(speedAcknowledged(rig, 333));
}

TEST(Garbage, UdpDatagramsOfWrongSizeToTheAppAreCountedAndIgnored) {
    Rig rig(Wire::Udp);
    ASSERT_TRUE(rig.start());
    const auto framesBefore = rig.transport->counters().framesIn;
    for (int size : WrongSizes)
        ASSERT_TRUE(sendDatagram(bytes(size), rig.appUdpPort()));
    ASSERT_TRUE(sendDatagram(frameWithDlcNine(), rig.appUdpPort()));
    ASSERT_TRUE(waitFor([&] { return rig.transport->counters().malformed == WrongSizes.size() + 1; }));
    EXPECT_EQ(rig.transport->counters().framesIn, framesBefore);
    EXPECT_EQ(rig.transport->state(), State::Connected);
    EXPECT_TRUE(speedAcknowledged(rig, 444));
}

TEST(Garbage, TcpJunkToTheStationIsCountedAndIgnored) {
    Rig rig(Wire::Tcp);
    ASSERT_TRUE(rig.start());
    QTcpSocket junk;
    junk.connectToHost(QHostAddress::LocalHost, rig.stationTcpPort());
    ASSERT_TRUE(waitFor([&] { return junk.state() == QAbstractSocket::ConnectedState; }));
    junk.write(bytes(39, '\xFF')); // three "frames" with DLC 255
    junk.write(frameWithDlcNine());
    junk.write(bytes(7)); // and a frame that never ends
    junk.disconnectFromHost();
    ASSERT_TRUE(waitFor(
        [&] { return rig.server->counters().malformedFrames == 4 && rig.server->tcpClientCount() == 1; }));
    // Nothing of it reached the app: the station's gateway drops what is not a frame.
    EXPECT_EQ(rig.transport->counters().malformed, 0U);
    EXPECT_TRUE(speedAcknowledged(rig, 555));
}

TEST(Garbage, FrameNoCommandHasIsIgnoredByStationAndCountedBySession) {
    Rig rig(Wire::Tcp);
    ASSERT_TRUE(rig.start());
    QTcpSocket otherController;
    otherController.connectToHost(QHostAddress::LocalHost, rig.stationTcpPort());
    ASSERT_TRUE(waitFor([&] { return rig.server->tcpClientCount() == 2; }));
    const auto answersBefore = rig.server->counters().framesOut;
    otherController.write(transport::encodeFrames(std::vector{undecodableFrame()}));
    // The gateway passes it on to the app, whose session cannot read it and leaves it; the station
    // (which got it first) did not answer it.
    ASSERT_TRUE(waitFor([&] { return rig.session->counters().undecodable == 1; }));
    EXPECT_EQ(rig.server->counters().framesOut, answersBefore)
        << "the station answered a frame it cannot read";
    EXPECT_TRUE(speedAcknowledged(rig, 666));
}

TEST(Garbage, TcpJunkToTheAppIsCountedAndIgnored) {
    Rig rig(Wire::Tcp);
    ASSERT_TRUE(rig.startServer());
    JunkRelay relay(rig.stationTcpPort());
    ASSERT_TRUE(relay.listening());
    rig.connectAppTo(relay.port());
    ASSERT_TRUE(rig.connectApp());

    relay.injectToApp(bytes(26, '\xFF') + frameWithDlcNine()); // three frames with a DLC above 8
    ASSERT_TRUE(waitFor([&] { return rig.transport->counters().malformed == 3; }));
    EXPECT_TRUE(speedAcknowledged(rig, 777));
}

TEST(Garbage, TcpConnectionEndingInsideAFrameIsCountedAndMadeAgain) {
    Rig rig(Wire::Tcp);
    ASSERT_TRUE(rig.startServer());
    JunkRelay relay(rig.stationTcpPort());
    ASSERT_TRUE(relay.listening());
    rig.connectAppTo(relay.port());
    ASSERT_TRUE(rig.connectApp());

    relay.endAppConnectionAfter(bytes(5)); // 5 bytes of 13
    ASSERT_TRUE(waitFor([&] { return rig.transport->counters().malformed == 1; }));
    ASSERT_TRUE(
        waitFor([&] { return rig.transport->state() == State::Connected && relay.connections() == 2; }));
    EXPECT_EQ(rig.transport->counters().reconnects, 1U);
    EXPECT_TRUE(speedAcknowledged(rig, 888));
}

} // namespace
} // namespace stellwerk::e2e
