// The app's demo (issue 15): the embedded station brings an OpenRailCAN decoder and encoder and an RO
// module on a device bus of its own; with the demo's bindings a route of the demo plan switches turnout
// W1 by an RO relay and signal A by a decoder output, and the siding's contact is an encoder input that
// reports the train standing there.

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "model/RailwayDevices.h"
#include "sim/EmbeddedStation.h"
#include "sim/SimulatedOrcDevices.h"
#include "sim/SimulatedRoModule.h"

#include <QSignalSpy>
#include <QTest>
#include <gtest/gtest.h>
#include <memory>

using namespace stellwerk;
using connection::ConnectionDevices;
using connection::StationConnection;

namespace {

constexpr int WaitMs = 10000;

// The GUI program's wiring: the demo devices with the embedded station, and the railway binding that makes
// a railway per session with its devices following the connection's sessions.
struct DemoApp {
    DemoApp() : connection(settings()), railways(connection) {
        railways.bindDevices([] { return model::DeviceBindings::demo(); });
    }
    static connection::ConnectionSettings settings() {
        connection::ConnectionSettings settings = support::withEmbeddedStation();
        settings.localStationDevices = connection::DeviceSettings::embeddedDemo();
        return settings;
    }
    model::Railway* railway() const { return railways.railway(); }

    StationConnection connection;
    binding::RailwayBinding railways;
};

TEST(EmbeddedDemoDevices, TheDemoStationsDevicesAreOnItsDeviceBus) {
    DemoApp app;
    app.connection.connectTo(QString());
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            const orccentral::OrcSession* orc = app.connection.devices().orcSession();
            const romodule::RoModuleSession* module =
                app.connection.devices().roModule(QStringLiteral("Demo RO"));
            return app.connection.state() == StationConnection::State::Ready && orc &&
                   orc->device(sim::EmbeddedStation::DemoOrcDecoder) &&
                   orc->device(sim::EmbeddedStation::DemoOrcEncoder) && module &&
                   module->state() == romodule::RoModuleSession::State::Online;
        },
        WaitMs))
        << app.connection.lastProblem().toStdString();
    ASSERT_EQ(app.connection.buses().list().size(), 2u);
    EXPECT_TRUE(app.connection.buses().list()[0].profile.expects(busreading::Protocol::Mcan))
        << "the demo MS1 keeps its bus";
    EXPECT_TRUE(app.connection.buses().list()[1].profile.expects(busreading::Protocol::Orc));
    EXPECT_EQ(app.connection.devices().orcSession()->device(sim::EmbeddedStation::DemoOrcDecoder)->busId,
              0x0101)
        << "the demo bindings name the decoder by this bus id";
    EXPECT_TRUE(app.connection.devices().refusals().isEmpty());
}

// Route 1 "Einfahrt Gleis 1": A Einfahrsignal (6) green, W1 Einfahrt West (1) to position 1, P1 (7).
TEST(EmbeddedDemoDevices, ARouteOfTheDemoPlanSwitchesTheRelayAndTheDecoderOutput) {
    DemoApp app;
    app.connection.connectTo(QString());
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            const orccentral::OrcSession* orc = app.connection.devices().orcSession();
            return app.railway() && app.railway()->isStateReported() && app.railway()->accessory(1) &&
                   app.railway()->accessory(1)->isPositionReported() && orc &&
                   orc->deviceAt(0x0101); // a decoder has no query: its outputs are known once switched
        },
        WaitMs));
    EXPECT_FALSE(app.railway()->accessory(6)->isPositionReported());
    QSignalSpy finished(app.railway(), &model::Railway::routeFinished);
    QSignalSpy failed(app.railway(), &model::Railway::routeFailed);
    ASSERT_TRUE(app.railway()->runRoute(1));
    ASSERT_TRUE(QTest::qWaitFor([&] { return finished.count() + failed.count() == 1; }, WaitMs));
    ASSERT_EQ(finished.count(), 1) << failed.at(0).at(1).toString().toStdString();
    EXPECT_EQ(app.railway()->accessory(1)->position(), 1);
    EXPECT_EQ(app.railway()->accessory(6)->position(), 1);
    EXPECT_TRUE(app.railway()->accessory(6)->isPositionReported());
    EXPECT_TRUE(app.railway()->isRouteSet(1));
}

TEST(EmbeddedDemoDevices, TheEncodersFirstInputIsTheSidingsOccupancyFromTheStart) {
    sim::EmbeddedStation station;
    ASSERT_TRUE(station.start());
    EXPECT_EQ(station.orcEncoder()->inputs() & 1u, 1u) << "the Köf is placed on the siding";
    EXPECT_EQ(station.orcEncoder()->inputs() & ~1u, 0u);
}

// Issue 32: the demo's encoder toggled the siding's contact every 5 s, a train that came and went while
// the Köf stood still. Its input 0 is the siding's occupancy detector: lit while the Köf stands there, and
// it stays lit while the demo's other input (the RO module's, contact 0/20) changes.
TEST(EmbeddedDemoDevices, TheSidingsContactIsLitByTheEncoderWhileTheKoefStandsThere) {
    DemoApp app;
    app.connection.connectTo(QString());
    const model::ContactKey siding = model::contactKey(0, sim::EmbeddedStation::DemoSidingContact);
    const model::ContactKey moduleInput = model::contactKey(0, 20);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            return app.railway() && app.railway()->contact(siding) &&
                   app.railway()->contact(siding)->known() && app.railway()->contact(moduleInput) &&
                   app.railway()->contact(moduleInput)->known();
        },
        WaitMs));
    EXPECT_TRUE(app.railways.devices()->lights(siding)) << "the encoder lights it, not the station's S88";
    EXPECT_TRUE(app.railway()->contact(siding)->occupied());
    const bool moduleFirst = app.railway()->contact(moduleInput)->occupied();
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return app.railway()->contact(moduleInput)->occupied() != moduleFirst; }, WaitMs))
        << "the demo's RO input still changes on its own";
    EXPECT_TRUE(app.railway()->contact(siding)->occupied()) << "no train came or went on the siding";
}

} // namespace
