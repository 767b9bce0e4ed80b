// The one place that binds the railway to the sessions (issue 33): with the embedded station the railway
// is made, bound to the handhelds and loaded, the layout in use holds the demo's pages and graph, a
// reconnect gives a new railway bound the same way, an opened folder wins over the station's download, and
// the devices are bound to each railway and rebound as their sessions come and go.

#include "binding/RailwayBinding.h"

#include "EmbeddedStationSupport.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "model/RailwayDevices.h"
#include "model/RailwayHandhelds.h"
#include "sim/EmbeddedStation.h"

#include <QSignalSpy>
#include <QTest>
#include <filesystem>
#include <gtest/gtest.h>

using namespace stellwerk;
using connection::StationConnection;

namespace {

constexpr int WaitMs = 10000;

// The embedded station with its demo devices, a layout in use and the binding between them.
struct BoundDemo {
    BoundDemo() : connection(settings()), railways(connection, &layout) {}
    static connection::ConnectionSettings settings() {
        connection::ConnectionSettings settings = support::withEmbeddedStation();
        settings.localStationDevices = connection::DeviceSettings::embeddedDemo();
        return settings;
    }
    bool ready() {
        return QTest::qWaitFor(
            [this] { return connection.state() == StationConnection::State::Ready && railways.railway(); },
            WaitMs);
    }

    StationConnection connection;
    model::LayoutInUse layout;
    binding::RailwayBinding railways;
};

std::filesystem::path demoFolder() {
    return std::filesystem::path(STELLWERK_SOURCE_DIR) / "resources/demo-layout";
}

TEST(RailwayBinding, WithTheEmbeddedStationTheRailwayIsLoadedAndTheLayoutInUseIsTheDemos) {
    BoundDemo demo;
    QSignalSpy changed(&demo.railways, &binding::RailwayBinding::railwayChanged);
    demo.connection.connectTo(QString());
    ASSERT_TRUE(demo.ready()) << demo.connection.lastProblem().toStdString();
    model::Railway* railway = demo.railways.railway();
    EXPECT_EQ(changed.count(), 1);
    ASSERT_NE(railway->accessory(1), nullptr) << "loaded with the station's files";
    EXPECT_EQ(railway->accessory(1)->name(), QStringLiteral("W1 Einfahrt West"));
    EXPECT_NE(railway->findChild<model::RailwayHandhelds*>(), nullptr) << "the demo MS1 drives it";
    EXPECT_EQ(demo.layout.origin(), model::LayoutInUse::Origin::Station);
    ASSERT_NE(demo.layout.pages(), nullptr);
    EXPECT_EQ(demo.layout.pages()->pages().size(), railway->layout().pages().size());
    EXPECT_EQ(demo.layout.pages()->pages().size(), 3U);
    ASSERT_NE(demo.layout.graph(), nullptr);
    EXPECT_EQ(demo.layout.graph()->blocks().size(), 9U);
    EXPECT_TRUE(demo.connection.pictures().folder().isEmpty()) << "pictures from the station";
}

TEST(RailwayBinding, AfterAReconnectANewRailwayIsBoundAndLoadedAndTheLayoutIsTheStationsAgain) {
    BoundDemo demo;
    demo.connection.connectTo(QString());
    ASSERT_TRUE(demo.ready());
    const auto firstGraph = demo.layout.graph();

    demo.connection.disconnectFromStation();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !demo.railways.railway(); }, WaitMs));
    EXPECT_EQ(demo.layout.origin(), model::LayoutInUse::Origin::None) << "the station went away";

    demo.connection.connectTo(QString());
    ASSERT_TRUE(demo.ready());
    model::Railway* railway = demo.railways.railway();
    ASSERT_NE(railway->accessory(1), nullptr);
    EXPECT_NE(railway->findChild<model::RailwayHandhelds*>(), nullptr);
    EXPECT_EQ(demo.layout.origin(), model::LayoutInUse::Origin::Station);
    ASSERT_NE(demo.layout.graph(), nullptr);
    EXPECT_NE(demo.layout.graph(), firstGraph) << "the new download's graph";
    EXPECT_EQ(demo.layout.graph()->blocks().size(), 9U);
}

TEST(RailwayBinding, AnOpenedFolderWinsOverTheDownloadAndLendsTheConnectionItsPictures) {
    BoundDemo demo;
    ASSERT_EQ(demo.layout.open(demoFolder()), "");
    EXPECT_EQ(demo.connection.pictures().folder(), QString::fromStdString((demoFolder() / "icons").string()));
    demo.connection.connectTo(QString());
    ASSERT_TRUE(demo.ready());
    ASSERT_NE(demo.railways.railway()->accessory(1), nullptr) << "the railway is the station's all the same";
    EXPECT_EQ(demo.layout.origin(), model::LayoutInUse::Origin::Folder);
    demo.layout.showStation();
    EXPECT_EQ(demo.layout.origin(), model::LayoutInUse::Origin::Station);
    EXPECT_EQ(demo.layout.pages()->pages().size(), 3U);
    EXPECT_TRUE(demo.connection.pictures().folder().isEmpty());
}

// The demo's bindings: the siding's contact is input 0 of the embedded station's encoder (lit while the
// Köf stands there); each railway is bound again, and bound to the sessions as they come.
TEST(RailwayBinding, DevicesAreBoundToEveryRailwayAndReboundAsTheirSessionsCome) {
    BoundDemo demo;
    int asked = 0;
    demo.railways.bindDevices([&asked] {
        ++asked;
        return model::DeviceBindings::demo();
    });
    const model::ContactKey siding = model::contactKey(0, sim::EmbeddedStation::DemoSidingContact);
    const auto sidingLit = [&] {
        model::Railway* railway = demo.railways.railway();
        return railway && demo.railways.devices() && demo.railways.devices()->lights(siding) &&
               railway->contact(siding) && railway->contact(siding)->occupied();
    };
    for (int connection = 1; connection <= 2; ++connection) {
        demo.connection.connectTo(QString());
        ASSERT_TRUE(demo.ready());
        EXPECT_EQ(asked, connection) << "the bindings are read for every railway";
        EXPECT_TRUE(QTest::qWaitFor(sidingLit, WaitMs)) << "connection " << connection;
        demo.connection.disconnectFromStation();
        ASSERT_TRUE(QTest::qWaitFor([&] { return !demo.railways.railway(); }, WaitMs));
    }
}

TEST(RailwayBinding, WithoutDeviceBindingsTheRailwayIsBoundToTheHandheldsOnly) {
    BoundDemo demo;
    demo.connection.connectTo(QString());
    ASSERT_TRUE(demo.ready());
    EXPECT_EQ(demo.railways.devices(), nullptr);
    EXPECT_EQ(demo.railways.railway()->findChild<model::RailwayDevices*>(), nullptr);
}

} // namespace
