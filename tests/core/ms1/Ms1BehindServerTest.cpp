// A simulated MS1 on the simulated CS2's bus, behind the station's server: a client over TCP sees its
// login and can answer it, as a master on the network side of a CS2 gateway would.

#include "Ms1TestSupport.h"
#include "cs2/Codec.h"
#include "cs2/Request.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "transport/FrameAssembler.h"
#include "transport/NetworkFraming.h"

#include <QTcpSocket>
#include <memory>

namespace stellwerk::sim::test {
namespace {

// A TCP client of the simulated CS2 on a bus it shares with an MS1, collecting what it receives.
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

TEST(Ms1BehindServer, AClientOverTcpSeesItsLoginAndCanAnswerIt) {
    SimulatedBus bus;
    SimulatedStation station(StationLayout::demo());
    SimulatedMs1 ms1(fastMs1());
    bus.attach(station);
    bus.attach(ms1);
    StationServerSettings settings;
    settings.listenAddress = QHostAddress::LocalHost;
    settings.udp = false;
    settings.tcpPort = 0;
    StationServer server(station, bus, settings);
    ASSERT_TRUE(server.listen()) << server.errorString().toStdString();
    TcpClient client(server.tcpPort());
    ASSERT_TRUE(client.connected());
    ASSERT_TRUE(waitFor([&] { return server.tcpClientCount() == 1; }));

    ms1.plugIn();
    ASSERT_TRUE(waitFor([&] { return client.frames.size() == 1; })) << "the MS1's stage 0";
    EXPECT_EQ(client.frames[0], frame("1C00007E 0"));
    client.send({frame("1C0030FE 8 00 04 84 D3 00 01 00 01")}); // a master's reply over TCP
    ASSERT_TRUE(waitFor([&] { return client.frames.size() == 2; }));
    EXPECT_EQ(client.frames[1], frame("1C08B07E 0")) << "the MS1 goes on with stage 1";

    const CanFrame ping = cs2::encode(cs2::request(cs2::Ping{}));
    client.send({ping});
    ASSERT_TRUE(waitFor([&] {
        return std::ranges::any_of(
            client.frames, [](const CanFrame& f) { return cs2::command(f) == 0x18 && cs2::isResponse(f); });
    })) << "the station answers as before";
    EXPECT_EQ(server.counters().framesIn, 2u);
}

} // namespace
} // namespace stellwerk::sim::test
