// Issue 15 end to end: OpenRailCAN devices and an RO module on the station's bus beside the simulated CS2,
// reached over UDP and over a CAN adapter (virtualcan). The app holds the connection as the GUI does, with
// the central and the module session on the station's bus, a railway per session and its devices bound
// by the demo's bindings. A route of the demo plan switches W1 by an RO relay and signal A by a decoder
// output; an encoder input lights the siding's contact. Asserted: the simulated devices' relays and
// outputs, what Stellwerk put on the wire, and what the railway reports.

#include "E2eSupport.h"
#include "connection/StationConnection.h"
#include "cs2/Codec.h"
#include "model/RailwayDevices.h"
#include "orc/Codec.h"
#include "ro/Codec.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedOrcDevices.h"
#include "sim/SimulatedRoModule.h"
#include "transport/TransportAddress.h"

#include <QSignalSpy>

namespace stellwerk::e2e {
namespace {

constexpr std::uint32_t DecoderUid = 0x3A2E0101; // bus id 0x0101, as DeviceBindings::demo() names it
constexpr std::uint32_t EncoderUid = 0x3A2E0102;
const model::ContactKey Siding = model::contactKey(0, 9);

ro::RoProfile moduleProfile() {
    ro::RoProfile profile = ro::RoProfile::simulator(1);
    profile.name = "Demo RO";
    return profile;
}

// The station's side: the simulated CS2 of the demo layout, RO module 1, an ORC decoder and an encoder on
// one bus behind the station's server.
class DeviceStation {
public:
    explicit DeviceStation(Wire wire) : station(sim::StationLayout::demo()), wire_(wire) {
        bus.attach(station);
        bus.attach(module);
        bus.attach(decoder);
        bus.attach(encoder);
        decoder.plugIn();
        encoder.plugIn();
        if (wire_ == Wire::Udp)
            appUdpPort_ = freeUdpPort();
    }
    bool listen() {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.tcp = false;
        settings.udp = wire_ == Wire::Udp;
        settings.udpReplyHost = QHostAddress::LocalHost;
        settings.udpReplyPort = appUdpPort_;
        settings.udpPort = 0;
        if (wire_ == Wire::VirtualCan)
            settings.canBus = virtualBus();
        server = std::make_unique<sim::StationServer>(station, bus, settings);
        return server->listen();
    }
    QString url() const {
        if (wire_ == Wire::Udp)
            return QStringLiteral("udp://127.0.0.1:%1?listen=%2").arg(server->udpPort()).arg(appUdpPort_);
        return transport::transportUrl(virtualBus());
    }

    sim::SimulatedBus bus;
    sim::SimulatedStation station;
    sim::SimulatedRoModule module{moduleProfile()};
    sim::SimulatedOrcDecoder decoder{DecoderUid};
    sim::SimulatedOrcEncoder encoder{EncoderUid};
    std::unique_ptr<sim::StationServer> server;

private:
    Wire wire_;
    std::uint16_t appUdpPort_ = 0;
};

// The app's side: the devices on the station's bus (bus 0), the railway and its devices, and every frame
// Stellwerk wrote there.
class DeviceApp {
public:
    DeviceApp() : connection(settings()) {
        QObject::connect(&connection, &connection::StationConnection::sessionStarted, &connection,
                         [this](station::StationSession* session) {
                             devices.reset();
                             railway = std::make_unique<model::Railway>(*session);
                             devices = std::make_unique<model::RailwayDevices>(*railway,
                                                                               model::DeviceBindings::demo());
                             follow();
                         });
        QObject::connect(&connection, &connection::StationConnection::configurationLoaded, &connection,
                         [this](const station::StartupResult& result) { railway->load(result); });
        QObject::connect(&connection.devices(), &connection::ConnectionDevices::devicesChanged, &connection,
                         [this] { follow(); });
        QObject::connect(&connection.buses(), &connection::ConnectionBuses::stationFramesSeen, &connection,
                         [this](const std::vector<can::CanFrame>& frames, bool outgoing) {
                             if (outgoing)
                                 sent.insert(sent.end(), frames.begin(), frames.end());
                         });
    }

    static connection::ConnectionSettings settings() {
        connection::ConnectionSettings settings;
        settings.session = sessionSettings();
        settings.startup.deviceWindow = 100ms;
        settings.startup.readStatusData = false;
        settings.devices = connection::DeviceSettings::embeddedDemo();
        settings.devices.orc.bus = 0;
        settings.devices.roModules.front().bus = 0;
        settings.devices.roModules.front().pollPeriod = 100ms;
        return settings;
    }
    void follow() {
        if (devices)
            devices->setSessions(connection.devices().orcSession(), connection.devices().roModules());
    }
    // Ready, the railway loaded, the module's relays read and the decoder given its bus id.
    bool ready() {
        return waitFor(
            [this] {
                const orccentral::OrcSession* orc = connection.devices().orcSession();
                const orccentral::OrcDevice* decoder = orc ? orc->device(DecoderUid) : nullptr;
                return connection.state() == connection::StationConnection::State::Ready && railway &&
                       railway->isStateReported() && railway->accessory(1)->isPositionReported() && decoder &&
                       decoder->state == orccentral::OrcDevice::State::Online;
            },
            3 * WaitMs);
    }
    // The frames Stellwerk wrote that `decode` reads as `T`.
    template <typename T, typename Decode>
    std::vector<T> sentAs(Decode decode) const {
        std::vector<T> found;
        for (const can::CanFrame& frame : sent)
            if (const auto message = decode(frame))
                found.push_back(*message);
        return found;
    }

    connection::StationConnection connection;
    std::unique_ptr<model::Railway> railway;
    std::unique_ptr<model::RailwayDevices> devices;
    std::vector<can::CanFrame> sent;
};

// The relay writes Stellwerk sent to the module: the values of its relay word.
std::vector<std::uint32_t> relayWrites(const DeviceApp& app) {
    const ro::RoProfile profile = moduleProfile();
    std::vector<std::uint32_t> values;
    for (const can::CanFrame& frame : app.sent) {
        if (ro::directionOf(frame, profile.ids) != ro::Direction::Request)
            continue;
        const auto request = ro::decodeRequest(frame.payload());
        if (request && request.value().kind == ro::Request::Kind::Write &&
            request.value().address == profile.outputs.address)
            values.push_back(request.value().value);
    }
    return values;
}

// The decoder switches Stellwerk sent: (Ziel-Id, Pos).
std::vector<std::pair<std::uint16_t, std::uint8_t>> decoderSwitches(const DeviceApp& app) {
    std::vector<std::pair<std::uint16_t, std::uint8_t>> switches;
    for (const can::CanFrame& frame : app.sent) {
        if (!orc::isOrc(frame))
            continue;
        const orc::Message message = orc::decode(frame);
        const auto* sw = std::get_if<orc::DecoderSwitch>(&message);
        if (sw && !sw->answer)
            switches.emplace_back(sw->target, sw->position);
    }
    return switches;
}

// CS2 accessory switchings Stellwerk sent to a wire address.
int cs2Switches(const DeviceApp& app, std::uint32_t address) {
    int count = 0;
    for (const can::CanFrame& frame : app.sent) {
        const auto message = cs2::decode(frame);
        const auto* sw = message ? std::get_if<cs2::AccessorySwitch>(&message->body) : nullptr;
        count += sw && !message->response && sw->article.value() == address ? 1 : 0;
    }
    return count;
}

class DevicesOverWire : public ::testing::TestWithParam<Wire> {};

// Route 1 "Einfahrt Gleis 1": A Einfahrsignal (6) green, W1 Einfahrt West (1) to position 1, P1 (7).
TEST_P(DevicesOverWire, ARouteSwitchesAnRoRelayAndAnOpenRailCanDecoderOutput) {
    DeviceStation station(GetParam());
    ASSERT_TRUE(station.listen());
    DeviceApp app;
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready()) << app.connection.lastProblem().toStdString();
    EXPECT_TRUE(app.connection.devices().refusals().isEmpty());

    QSignalSpy finished(app.railway.get(), &model::Railway::routeFinished);
    QSignalSpy failed(app.railway.get(), &model::Railway::routeFailed);
    ASSERT_TRUE(app.railway->runRoute(1));
    ASSERT_TRUE(waitFor([&] { return finished.count() + failed.count() == 1; }, 3 * WaitMs));
    ASSERT_EQ(finished.count(), 1) << failed.at(0).at(1).toString().toStdString();

    EXPECT_TRUE(station.module.relay(1)) << "W1 is relay 1";
    EXPECT_EQ(station.decoder.outputs() & 0x01, 0x01) << "signal A is output 0";
    EXPECT_EQ(relayWrites(app), std::vector<std::uint32_t>{0x0001});
    EXPECT_EQ(decoderSwitches(app), (std::vector<std::pair<std::uint16_t, std::uint8_t>>{{0x0101, 0x01}}));
    EXPECT_EQ(app.railway->accessory(1)->position(), 1);
    EXPECT_TRUE(app.railway->accessory(6)->isPositionReported());
    EXPECT_EQ(app.railway->accessory(6)->position(), 1);
    EXPECT_TRUE(app.railway->isRouteSet(1));
    EXPECT_EQ(cs2Switches(app, 0x3000), 0) << "W1 (MM2 address 1) never went to the CS2";
    EXPECT_EQ(cs2Switches(app, 0x3005), 0) << "nor signal A (MM2 address 6)";
}

// Nothing reported switched that was not: with the module unplugged W1 is "not reported", the route stops
// at it with the reason, and no relay write leaves Stellwerk for an offline module.
TEST_P(DevicesOverWire, ARouteStopsAtARelayOfAnOfflineModule) {
    DeviceStation station(GetParam());
    ASSERT_TRUE(station.listen());
    DeviceApp app;
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready());
    station.module.unplug();
    ASSERT_TRUE(waitFor([&] { return !app.railway->accessory(1)->isPositionReported(); }));
    QSignalSpy failed(app.railway.get(), &model::Railway::routeFailed);
    ASSERT_TRUE(app.railway->runRoute(1));
    ASSERT_TRUE(waitFor([&] { return failed.count() == 1; }, 3 * WaitMs));
    EXPECT_NE(failed.at(0).at(1).toString().indexOf(QStringLiteral("\"Demo RO\" is offline")), -1)
        << failed.at(0).at(1).toString().toStdString();
    EXPECT_TRUE(relayWrites(app).empty());
    EXPECT_FALSE(station.module.relay(1));
    EXPECT_FALSE(app.railway->accessory(1)->isPositionReported());
    EXPECT_FALSE(app.railway->isRouteSet(1));
}

TEST_P(DevicesOverWire, AnEncoderInputLightsTheContactOnThePlan) {
    DeviceStation station(GetParam());
    ASSERT_TRUE(station.listen());
    DeviceApp app;
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready());
    QSignalSpy contacts(app.railway.get(), &model::Railway::contactsChanged);
    station.encoder.setInput(0, true);
    ASSERT_TRUE(waitFor([&] {
        const model::FeedbackContact* contact = app.railway->contact(Siding);
        return contact && contact->known() && contact->occupied();
    }));
    station.encoder.setInput(0, false);
    ASSERT_TRUE(waitFor([&] { return !app.railway->contact(Siding)->occupied(); }));
    EXPECT_GE(contacts.count(), 2);
}

INSTANTIATE_TEST_SUITE_P(Wires, DevicesOverWire, ::testing::Values(Wire::Udp, Wire::VirtualCan),
                         [](const auto& info) { return wireName(info.param); });

} // namespace
} // namespace stellwerk::e2e
