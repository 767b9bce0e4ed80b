// The command line's path through the one place that binds the railway (issue 33): a command that runs
// its session itself (StationClient, as `handhelds` and `resync` do) tells the binding what happens, and
// the railway is loaded and the layout in use holds the demo's pages and graph as in the window.

#include "CliApplication.h"
#include "StationClient.h"
#include "binding/RailwayBinding.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "station/StartupSequence.h"

#include <QCoreApplication>
#include <QTest>
#include <gtest/gtest.h>
#include <sstream>

using namespace stellwerk;

namespace {

TEST(CliRailwayBinding, ACommandsOwnSessionLoadsTheRailwayAndTheLayoutInUse) {
    stellwerk::cli::test::ensureApplication();
    sim::SimulatedStation station(sim::StationLayout::demo());
    sim::StationServerSettings settings;
    settings.listenAddress = QHostAddress::LocalHost;
    settings.udp = false;
    settings.tcpPort = 0;
    sim::StationServer server(station, settings);
    ASSERT_TRUE(server.listen()) << server.errorString().toStdString();
    std::ostringstream err;
    cli::StationClient client(err);
    ASSERT_EQ(client.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(server.tcpPort())), 0) << err.str();

    model::LayoutInUse layout;
    binding::RailwayBinding railways(&layout);
    railways.sessionStarted(client.session(), nullptr);
    ASSERT_NE(railways.railway(), nullptr) << "made before the start-up runs";
    station::StartupSequence startup(client.session());
    QObject::connect(&startup, &station::StartupSequence::ready, &railways,
                     &binding::RailwayBinding::configurationLoaded);
    startup.start();
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return layout.origin() == model::LayoutInUse::Origin::Station; }, 10000))
        << err.str();
    ASSERT_NE(railways.railway()->accessory(1), nullptr);
    EXPECT_EQ(railways.railway()->accessory(1)->name(), QStringLiteral("W1 Einfahrt West"));
    ASSERT_NE(layout.pages(), nullptr);
    EXPECT_EQ(layout.pages()->pages().size(), 3U);
    ASSERT_NE(layout.graph(), nullptr);
    EXPECT_EQ(layout.graph()->blocks().size(), 9U);

    railways.sessionEnded();
    EXPECT_EQ(railways.railway(), nullptr);
    EXPECT_EQ(layout.origin(), model::LayoutInUse::Origin::None);
}

} // namespace
