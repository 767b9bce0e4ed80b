// The states other programs announce on the station's bus (CS2 chapter 9, 0x30) on the track plan: beside
// the names of the blocks they address ("unknown" for a state the document does not name), in the blocks'
// tooltips, and the route buttons' menu asking the station to run a route from its memory; English and
// German.
#include "EmbeddedStationSupport.h"
#include "TrackPlanOnDemoStation.h"
#include "binding/RailwayBinding.h"
#include "cs2/Codec.h"
#include "model/BlockStates.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "shell/Translations.h"
#include "support/StationTestSupport.h"
#include "trackgraph/TrackGraph.h"
#include "trackplan/BlockOutlines.h"
#include "trackplan/BlockViewSettings.h"
#include "trackplan/PlanGraph.h"
#include "trackplan/TrackPageView.h"
#include "trackplan/TrackPlanPanel.h"
#include "transport/NetworkFraming.h"

#include <QAction>
#include <QMenu>
#include <QTabWidget>
#include <QTcpSocket>
#include <QTest>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

class TrackPlanBlockStatesTest : public test::TrackPlanOnDemoStation {
protected:
    void SetUp() override {
        TrackPlanOnDemoStation::SetUp();
        other.connectToHost(QHostAddress::LocalHost, server.port());
        ASSERT_TRUE(other.waitForConnected(5000));
    }
    // Another program on the station says a state for one of Stellwerk's blocks.
    void announce(int block, std::uint8_t value) {
        const auto address = model::BlockStates::addressOfBlock(block);
        ASSERT_TRUE(address.has_value());
        const can::CanFrame frame = cs2::encode(
            cs2::Message{0, true, 0x2B11,
                         cs2::AutomationSwitch{address->device, address->function, value, 0, std::nullopt}});
        other.write(transport::encodeFrames({&frame, 1}));
        other.flush();
    }
    int blockNamed(const std::string& name) const {
        for (const trackgraph::Block& block : panel->graph()->graph().blocks())
            if (block.name == name)
                return block.id;
        ADD_FAILURE() << "no block " << name;
        return 0;
    }
    QStringList tabNames(int page) const {
        QStringList names;
        for (const BlockOutlines::Block& block : panel->pageView(page)->blocks().blocks())
            names << block.name;
        return names;
    }
    model::TileRef routeTile(std::int64_t route) const {
        const auto& pages = panel->layout()->pages();
        for (int p = 0; p < int(pages.size()); ++p)
            for (int t = 0; t < int(pages[std::size_t(p)].tiles.size()); ++t)
                if (pages[std::size_t(p)].tiles[std::size_t(t)].route == route)
                    return {p, t};
        ADD_FAILURE() << "no route button " << route;
        return {};
    }
    void selectGerman() {
        ASSERT_TRUE(translations.select(Language::German));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }
    void save(const QString& name) {
        panel->pageTabs()->setCurrentIndex(0);
        panel->fitToWindow();
        QCoreApplication::processEvents();
        const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
        if (!folder.isEmpty())
            panel->grab().save(folder + QLatin1Char('/') + name);
    }

    QTcpSocket other;
};

TEST_F(TrackPlanBlockStatesTest, AnnouncedStatesStandBesideTheBlocksNamesAndUnknownValuesAreUnknown) {
    panel->setShowBlocks(true);
    const int gleis1 = blockNamed("Gleis 1");
    const int gleis2 = blockNamed("Gleis 2");
    announce(gleis1, 4); // occupied
    announce(gleis2, 7); // a value the document does not define
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return tabNames(0).contains(QStringLiteral("Gleis 2 · unknown")); }, 5000))
        << tabNames(0).join(QStringLiteral(", ")).toStdString();
    EXPECT_TRUE(tabNames(0).contains(QStringLiteral("Gleis 1 · occupied")));
    EXPECT_TRUE(tabNames(0).contains(QStringLiteral("Abstellgleis"))) << "nothing said: the name alone";
    const auto& pages = panel->layout()->pages();
    bool tipSaid = false;
    for (int t = 0; t < int(pages[0].tiles.size()); ++t)
        if (panel->graph()->blocksAt({0, t}) == std::vector<int>{gleis1})
            tipSaid =
                panel->toolTipOf({0, t}).contains(QStringLiteral("Announced on the station's bus: occupied"));
    EXPECT_TRUE(tipSaid);
    save(QStringLiteral("block-states.png"));
    selectGerman();
    EXPECT_TRUE(tabNames(0).contains(QStringLiteral("Gleis 1 · besetzt"))) << "the language follows at once";
    EXPECT_TRUE(tabNames(0).contains(QStringLiteral("Gleis 2 · unbekannt")));
    announce(gleis1, 6); // reserved
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return tabNames(0).contains(QStringLiteral("Gleis 1 · reserviert")); }, 5000))
        << tabNames(0).join(QStringLiteral(", ")).toStdString();
    save(QStringLiteral("block-states-de.png"));
}

TEST_F(TrackPlanBlockStatesTest, NothingIsSaidWhileTheBlocksAreHidden) {
    announce(4, 4); // "Gleis 1" is block 4 of the demo
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return railways.railway()->blockStates().blockState(4).has_value(); }, 5000));
    EXPECT_TRUE(panel->pageView(0)->blocks().isEmpty());
    panel->setShowBlocks(true);
    EXPECT_TRUE(tabNames(0).contains(QStringLiteral("Gleis 1 · occupied")));
}

// Route 2 "Einfahrt Gleis 2" from the station's memory (slot A2): the station switches it, the plan shows the
// turnouts where the route leaves them, and the button's tooltip says the station marks it active.
TEST_F(TrackPlanBlockStatesTest, TheRouteMenuAsksTheStationToRunTheRouteFromItsMemory) {
    const model::TileRef button = routeTile(2);
    QMenu menu;
    ASSERT_TRUE(panel->fillTileMenu(menu, button));
    QAction* entry = menu.findChild<QAction*>(QStringLiteral("memoryEntry"));
    ASSERT_NE(entry, nullptr);
    EXPECT_EQ(entry->text(), QStringLiteral("Run from the station's memory (A2)"));
    EXPECT_TRUE(panel->toolTipOf(button).contains(QStringLiteral("Station memory A2")));
    model::Railway& railway = *railways.railway();
    ASSERT_EQ(railway.accessory(1)->position(), 1);
    entry->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return railway.accessory(1)->position() == 0; }, 5000));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return panel->toolTipOf(button).contains(QStringLiteral("Station memory A2: active")); },
        5000));
    EXPECT_EQ(railway.accessory(2)->position(), 0);
    EXPECT_EQ(server.station().accessoryPosition(0x3005), 1); // A Einfahrsignal green
    selectGerman();
    QMenu german;
    ASSERT_TRUE(panel->fillTileMenu(german, button));
    EXPECT_EQ(german.findChild<QAction*>(QStringLiteral("memoryEntry"))->text(),
              QStringLiteral("Aus dem Speicher der Zentrale stellen (A2)"));
}

} // namespace
