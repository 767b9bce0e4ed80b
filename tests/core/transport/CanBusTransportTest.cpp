// QCanBus devices through Qt's virtualcan plugin: no kernel vcan needed. The plugin starts one TCP relay
// per process on the port named in the interface; each test process picks its own free port, so tests
// running in parallel processes never share a bus.

#include "transport/CanBusTransport.h"

#include "TestSupport.h"

#include <QCanBus>
#include <QCanBusFrame>
#include <QTcpServer>
#include <QTcpSocket>

namespace stellwerk::transport::test {
namespace {

using State = Transport::State;

// The virtual bus of this test process, "can0" of the relay on a port nobody else uses.
QString virtualBus() {
    static const std::uint16_t port = freeTcpPort();
    return QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port);
}

CanBusSettings virtualBusSettings() {
    CanBusSettings settings;
    settings.plugin = QStringLiteral("virtualcan");
    settings.interfaceName = virtualBus();
    settings.reconnect = fastReconnect();
    return settings;
}

// Two transports on one virtual bus, both connected and heard by each other.
struct Bus {
    CanBusTransport app{virtualBusSettings()};
    CanBusTransport station{virtualBusSettings()};
    Recorder appReceived{app};
    Recorder stationReceived{station};

    bool open() {
        app.open();
        station.open();
        return waitForState(app, State::Connected) && waitForState(station, State::Connected) && settle();
    }

    // A virtualcan device is connected before the relay has registered it for its bus, and the relay
    // drops frames for devices it does not know yet. Probes go both ways until each side hears the
    // other; a last probe from each side then flushes out the earlier ones, and the recordings restart.
    bool settle() {
        const CanFrame probe = frame(cs2::makeId(0, 0x18, false, 0xFFFF), {});
        const bool heard = waitFor([&] {
            app.send(probe);
            station.send(probe);
            return appReceived.frameCount() > 0 && stationReceived.frameCount() > 0;
        });
        const std::size_t appBefore = appReceived.frameCount();
        const std::size_t stationBefore = stationReceived.frameCount();
        const CanFrame last = frame(cs2::makeId(0, 0x18, true, 0xFFFF), {});
        app.send(last);
        station.send(last);
        const bool flushed = waitFor([&] {
            return !appReceived.frames().empty() && appReceived.frameCount() > appBefore &&
                   appReceived.frames().back() == last && stationReceived.frameCount() > stationBefore &&
                   stationReceived.frames().back() == last;
        });
        appReceived.clearFrames();
        stationReceived.clearFrames();
        return heard && flushed;
    }
};

TEST(CanBusTransport, VirtualCanInterfacesAreListed) {
    const auto interfaces = CanBusTransport::availableInterfaces();
    const bool listed = std::any_of(interfaces.begin(), interfaces.end(), [](const CanBusInterface& each) {
        return each.plugin == QLatin1String("virtualcan") && each.name == QLatin1String("can0");
    });
    EXPECT_TRUE(listed);
}

TEST(CanBusTransport, TwoTransportsOnOneVirtualBusTalkToEachOther) {
    Bus bus;
    ASSERT_TRUE(bus.open());
    const std::vector<CanFrame> toStation{
        frame(0x00004711, {0, 0, 0, 0, 1}), frame(0x1FFFFFFF, {}),
        frame(cs2::makeId(0, 0x18, true, 0x0300), {1, 2, 3, 4, 5, 6, 7, 8})};
    const TransportCounters before = bus.app.counters();
    EXPECT_EQ(bus.app.sendBatch(toStation), 3u);
    ASSERT_TRUE(bus.stationReceived.waitForFrames(3));
    EXPECT_EQ(bus.stationReceived.frames(), toStation);

    EXPECT_EQ(bus.station.sendBatch(numberedFrames(50)), 50u);
    ASSERT_TRUE(bus.appReceived.waitForFrames(50));
    EXPECT_EQ(bus.appReceived.frames(), numberedFrames(50));
    EXPECT_EQ(bus.app.counters().framesOut - before.framesOut, 3u);
    EXPECT_EQ(bus.app.counters().framesIn - before.framesIn, 50u);
}

// Both frame formats belong to protocols on the bus (M-CAN, OpenRailCAN and RO modules use 11-bit ids):
// a standard frame arrives as one, an extended frame with a small id keeps its format. Remote frames
// belong to no protocol and are counted.
TEST(CanBusTransport, StandardAndExtendedFramesArriveInTheirFormat) {
    Bus bus;
    ASSERT_TRUE(bus.open());
    std::unique_ptr<QCanBusDevice> other(
        QCanBus::instance()->createDevice(QStringLiteral("virtualcan"), virtualBus()));
    ASSERT_TRUE(other);
    ASSERT_TRUE(other->connectDevice());
    ASSERT_TRUE(waitFor([&] { return other->state() == QCanBusDevice::ConnectedState; }));
    QCanBusFrame remote(0x321, QByteArray());
    remote.setFrameType(QCanBusFrame::RemoteRequestFrame);
    remote.setExtendedFrameFormat(false);
    EXPECT_TRUE(other->writeFrame(remote));
    QCanBusFrame standard(0x123, QByteArray("\x01\x02", 2));
    standard.setExtendedFrameFormat(false);
    EXPECT_TRUE(other->writeFrame(standard));
    QCanBusFrame extended(0x00000123, QByteArray(5, '\0'));
    extended.setExtendedFrameFormat(true);
    EXPECT_TRUE(other->writeFrame(extended));
    ASSERT_TRUE(bus.appReceived.waitForFrames(2));
    const std::uint8_t two[] = {1, 2};
    const std::uint8_t five[5] = {};
    EXPECT_EQ(bus.appReceived.frames(),
              (std::vector{can::CanFrame::standard(0x123, two), can::CanFrame::extendedFrame(0x123, five)}));
    EXPECT_EQ(bus.app.counters().malformed, 1u) << "the remote frame";
    other->disconnectDevice();
}

// What the transport writes keeps its format, whatever the id: QCanBusFrame would otherwise guess
// "standard" for a 29-bit frame whose id fits 11 bits.
TEST(CanBusTransport, SendsEachFrameInItsOwnFormat) {
    Bus bus;
    ASSERT_TRUE(bus.open());
    const std::uint8_t payload[] = {0xAB};
    const std::vector sent{can::CanFrame::standard(0x7FF, payload),
                           can::CanFrame::extendedFrame(0x7FF, payload)};
    EXPECT_EQ(bus.app.sendBatch(sent), 2u);
    ASSERT_TRUE(bus.stationReceived.waitForFrames(2));
    EXPECT_EQ(bus.stationReceived.frames(), sent);
}

TEST(CanBusTransport, UnknownPluginIsReportedAndRetried) {
    CanBusSettings settings = virtualBusSettings();
    settings.plugin = QStringLiteral("nosuchplugin");
    CanBusTransport transport(settings);
    Recorder recorder(transport);
    transport.open();
    ASSERT_TRUE(waitFor([&] { return recorder.problems.size() >= 2; }));
    EXPECT_TRUE(recorder.problems[0].contains(QLatin1String("can://nosuchplugin/")))
        << recorder.problems[0].toStdString();
    EXPECT_EQ(transport.state(), State::Reconnecting);
    EXPECT_TRUE(transport.send(numbered(1))) << "frames wait for the interface";
    transport.close();
    EXPECT_EQ(transport.counters().dropped, 1u);
}

// A relay that speaks the virtualcan line protocol ("can0:<id>#<flags>#<hex>") and can drop its client,
// as an interface that vanishes (a USB adapter pulled out).
class VanishingInterface {
public:
    VanishingInterface() {
        EXPECT_TRUE(server_.listen(QHostAddress::LocalHost, 0));
        QObject::connect(&server_, &QTcpServer::newConnection, &server_, [this] {
            client_.reset(server_.nextPendingConnection());
            client_->setParent(nullptr);
            QObject::connect(client_.get(), &QTcpSocket::readyRead, client_.get(),
                             [this] { lines_.append(client_->readAll()); });
            ++connections_;
        });
    }
    QString interfaceName() const {
        return QStringLiteral("tcp://127.0.0.1:%1/can0").arg(server_.serverPort());
    }
    void dropClient() { client_->abort(); }
    void send(const QByteArray& line) { client_->write(line + '\n'); }
    int connections() const { return connections_; }
    const QByteArray& lines() const { return lines_; }

private:
    QTcpServer server_;
    std::unique_ptr<QTcpSocket> client_;
    QByteArray lines_;
    int connections_ = 0;
};

TEST(CanBusTransport, InterfaceThatGoesAwayIsReconnectedAndGetsNothingSentMeanwhile) {
    VanishingInterface interface;
    CanBusSettings settings = virtualBusSettings();
    settings.interfaceName = interface.interfaceName();
    CanBusTransport transport(settings);
    Recorder recorder(transport);
    transport.open();
    ASSERT_TRUE(waitForState(transport, State::Connected));

    interface.dropClient();
    ASSERT_TRUE(waitForState(transport, State::Reconnecting));
    EXPECT_FALSE(recorder.problems.empty());
    EXPECT_FALSE(transport.send(frame(0x00004711, {0, 0, 0, 0, 2}))) << "refused while the bus is away";
    ASSERT_TRUE(waitForState(transport, State::Connected));
    EXPECT_EQ(interface.connections(), 2);
    EXPECT_EQ(transport.counters().reconnects, 1u);
    EXPECT_TRUE(transport.send(frame(0x00004711, {0, 0, 0, 0, 1})));
    ASSERT_TRUE(waitFor([&] { return interface.lines().contains("#X#0000000001"); }));
    EXPECT_FALSE(interface.lines().contains("#X#0000000002")) << interface.lines().toStdString();
    EXPECT_TRUE(
        interface.lines().contains(QByteArray("can0:") + QByteArray::number(0x00004711) + "#X#0000000001"))
        << interface.lines().toStdString();

    interface.send(QByteArray::number(0x00004711) + "#X#0000000000");
    ASSERT_TRUE(recorder.waitForFrames(1));
    EXPECT_EQ(recorder.frames(), std::vector{frame(0x00004711, {0, 0, 0, 0, 0})});
}

TEST(CanBusTransport, PacingSpacesFramesOnTheBus) {
    constexpr auto gap = 10ms;
    Bus bus;
    bus.app.setPacing(gap);
    ASSERT_TRUE(bus.open());
    EXPECT_EQ(bus.app.sendBatch(numberedFrames(6)), 6u);
    ASSERT_TRUE(bus.stationReceived.waitForFrames(6));
    EXPECT_EQ(bus.stationReceived.frames(), numberedFrames(6));
    const qint64 span = bus.stationReceived.batchTimesNs.back() - bus.stationReceived.batchTimesNs.front();
    EXPECT_GE(span, std::chrono::nanoseconds(gap).count() * 5 * 8 / 10);
}

} // namespace
} // namespace stellwerk::transport::test
