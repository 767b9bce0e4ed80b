// Issue 34 on the track plan: the automation's blocks shaded (a train in it with its name, reserved for a
// train with its way's turnouts, an unknown occupant, a fault), a legend, trains placed from a block's menu
// and by dropping a locomotive on a block, and three trains running on the demo, English and German.
#include "EmbeddedStationSupport.h"
#include "TrackPlanOnDemoStation.h"
#include "automation/Automation.h"
#include "binding/RailwayBinding.h"
#include "common/LocomotiveMime.h"
#include "common/PlaceTrainDialog.h"
#include "locomotives/LocomotiveFileModel.h"
#include "locomotives/LocomotivePanel.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "shell/Translations.h"
#include "sim/TrainMovement.h"
#include "sim/TrainPlacement.h"
#include "support/StationTestSupport.h"
#include "trackgraph/TrackGraph.h"
#include "trackplan/BlockLegend.h"
#include "trackplan/BlockOutlines.h"
#include "trackplan/BlockViewSettings.h"
#include "trackplan/PlanAutomation.h"
#include "trackplan/PlanGraph.h"
#include "trackplan/TrackColors.h"
#include "trackplan/TrackPageView.h"
#include "trackplan/TrackPlanPanel.h"

#include <QAction>
#include <QDropEvent>
#include <QMenu>
#include <QMimeData>
#include <QTabWidget>
#include <QTest>
#include <gtest/gtest.h>
#include <memory>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;
using trackgraph::End;

namespace {

constexpr std::uint32_t AutoBr218 = 0x4001, Ice = 0x4002, V100 = 0x0018;
// The demo's blocks (tests/core/automation/AutomationTestSupport.h).
constexpr int Gleis2 = 1, Gleis1 = 4, AusfahrtOst = 5, Block1 = 6, Block3 = 8;

class TrackPlanAutomationTest : public test::TrackPlanOnDemoStation {
protected:
    void SetUp() override {
        TrackPlanOnDemoStation::SetUp();
        ASSERT_NE(layout.graph(), nullptr);
        graph = layout.graph();
    }
    void TearDown() override {
        automation.reset();
        TrackPlanOnDemoStation::TearDown();
    }
    void runAutomation(std::vector<sim::TrainPlacement> placements = {}) {
        automation = std::make_unique<automation::Automation>(*railways.railway(), *graph);
        automation->setClock([this] { return now; });
        for (const sim::TrainPlacement& placement : placements)
            ASSERT_EQ(automation->place(placement.locId, placement.contact, placement.towards), std::nullopt);
        panel->setAutomation(automation.get());
    }
    // The block's part on the first page that draws it.
    const BlockOutlines::Block* shown(int block) const {
        for (int page = 0; page < panel->pageTabs()->count(); ++page)
            if (const TrackPageView* view = panel->pageView(page))
                for (const BlockOutlines::Block& part : view->blocks().blocks())
                    if (part.id == block)
                        return &part;
        return nullptr;
    }
    QString nameShown(int block) const {
        const BlockOutlines::Block* part = shown(block);
        return part ? part->name : QString();
    }
    BlockShade shadeShown(int block) const {
        const BlockOutlines::Block* part = shown(block);
        return part ? part->shade : BlockShade::Plain;
    }
    // A tile of the block on the first page.
    model::TileRef tileOf(int block) const {
        const auto& tiles = panel->layout()->pages()[0].tiles;
        for (int t = 0; t < int(tiles.size()); ++t)
            if (panel->graph()->blocksAt({0, t}) == std::vector<int>{block})
                return {0, t};
        ADD_FAILURE() << "no tile of block " << block;
        return {};
    }
    QAction* menuAction(QMenu& menu, const QString& name) const {
        for (QAction* action : menu.actions())
            if (action->objectName() == name)
                return action;
        return nullptr;
    }
    void setContact(std::uint16_t number, bool occupied) {
        server.station().setContact(0, number, occupied);
        ASSERT_TRUE(QTest::qWaitFor(
            [&] {
                const model::FeedbackContact* contact =
                    railways.railway()->contact(model::contactKey(0, number));
                return contact && contact->known() && contact->occupied() == occupied;
            },
            5000));
        QCoreApplication::processEvents(); // the plan reads the automation once per batch
    }
    QImage painted() {
        panel->pageTabs()->setCurrentIndex(0);
        QCoreApplication::processEvents();
        return panel->pageView(0)->grab().toImage();
    }
    void selectGerman() {
        ASSERT_TRUE(translations.select(Language::German));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }
    void save(const QString& name) {
        QCoreApplication::processEvents(); // the layouts follow a language change
        const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
        if (!folder.isEmpty())
            panel->grab().save(folder + QLatin1Char('/') + name);
    }

    std::shared_ptr<const trackgraph::TrackGraph> graph;
    std::unique_ptr<automation::Automation> automation;
    automation::Millis now = 0;
};

bool near(QColor a, QColor b, int tolerance = 4) {
    return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

QColor over(const QColor& top, const QColor& under) {
    const double a = top.alphaF();
    return QColor::fromRgbF(float(top.redF() * a + under.redF() * (1 - a)),
                            float(top.greenF() * a + under.greenF() * (1 - a)),
                            float(top.blueF() * a + under.blueF() * (1 - a)));
}

TEST_F(TrackPlanAutomationTest, WithoutAnAutomationThePlanShowsNoTrainsAndOffersNoPlacing) {
    EXPECT_TRUE(panel->pageView(0)->blocks().isEmpty());
    EXPECT_FALSE(panel->blockLegend()->isVisible());
    EXPECT_FALSE(panel->pageView(0)->acceptDrops());
    QMenu menu;
    panel->fillTileMenu(menu, tileOf(Gleis1));
    EXPECT_EQ(menuAction(menu, QStringLiteral("placeTrainAction")), nullptr);
    runAutomation();
    automation.reset(); // deleted: the plan is as before
    QCoreApplication::processEvents();
    EXPECT_TRUE(panel->pageView(0)->blocks().isEmpty());
    EXPECT_FALSE(panel->blockLegend()->isVisible());
}

TEST_F(TrackPlanAutomationTest, APlacedTrainsBlockIsSolidWithItsNameOnTheTab) {
    runAutomation();
    EXPECT_TRUE(panel->blockLegend()->isVisible());
    EXPECT_TRUE(panel->pageView(0)->blocks().isEmpty()) << "free blocks are drawn only with Blocks on";
    ASSERT_EQ(automation->placeInBlock(AutoBr218, Gleis1, End::B), std::nullopt);
    QCoreApplication::processEvents();
    EXPECT_EQ(panel->planAutomation().trains().trainIn(Gleis1), AutoBr218);
    EXPECT_EQ(shadeShown(Gleis1), BlockShade::Occupied);
    EXPECT_EQ(nameShown(Gleis1), QStringLiteral("Gleis 1 · BR 218 Ost"));
    EXPECT_EQ(shown(Gleis2), nullptr) << "a free block stays undrawn";
    const QString tip = panel->toolTipOf(tileOf(Gleis1));
    EXPECT_TRUE(tip.contains(QStringLiteral("Automation: BR 218 Ost is in this block (solid)")))
        << tip.toStdString();

    const QImage image = painted();
    const TrackColors colors = TrackColors::from(panel->pageView(0)->palette());
    const BlockShadeLook look = BlockShadeLook::of(BlockShade::Occupied, colors);
    const QRect band = panel->pageView(0)->blocks().bandRect(Gleis1);
    const QRect tab = panel->pageView(0)->blocks().nameRect(Gleis1);
    ASSERT_FALSE(band.isEmpty());
    ASSERT_FALSE(tab.isEmpty());
    const qreal ratio = image.devicePixelRatio();
    const auto pixel = [&](QPoint p) { return image.pixelColor((QPointF(p) * ratio).toPoint()); };
    EXPECT_TRUE(near(pixel(QPoint(band.center().x(), band.top() + 1)), look.edge)) << "the band's edge";
    EXPECT_TRUE(
        near(pixel(QPoint(band.left() + 4, band.top() + 4)), over(look.band.color(), colors.background)))
        << "the solid band";
    EXPECT_TRUE(near(pixel(QPoint(tab.left() + 2, tab.center().y())), look.edge)) << "the name's tab";
    int namePixels = 0; // the name painted in the tab's text colour
    for (int x = tab.left(); x <= tab.right(); ++x)
        namePixels += near(pixel(QPoint(x, tab.center().y())), look.text, 60);
    EXPECT_GT(namePixels, 5);
}

TEST_F(TrackPlanAutomationTest, AReservedWayIsHatchedWithTheTrainsNameAndCoversItsTurnouts) {
    setContact(1, true);
    runAutomation({{AutoBr218, 1, End::B}});
    automation->start(std::chrono::milliseconds(0));
    automation->tick();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shadeShown(Block1) == BlockShade::Reserved; }, 3000));
    EXPECT_EQ(nameShown(AusfahrtOst), QStringLiteral("Ausfahrt Ost · for BR 218 Ost"));
    EXPECT_EQ(shadeShown(Gleis1), BlockShade::Occupied);
    const std::vector<int> ways = panel->planAutomation().trains().ways();
    ASSERT_FALSE(ways.empty());
    bool turnoutCovered = false;
    for (const int id : ways)
        for (const trackgraph::TurnoutOnWay& turnout : graph->connection(id).turnouts) {
            const BlockOutlines::Block* way = shown(-id);
            ASSERT_NE(way, nullptr) << "connection " << id;
            EXPECT_EQ(way->shade, BlockShade::Reserved);
            const trackgraph::TilePlace& place = graph->tile(turnout.tile).place;
            turnoutCovered = turnoutCovered || std::find(way->cells.begin(), way->cells.end(),
                                                         QPoint(place.column, place.row)) != way->cells.end();
        }
    EXPECT_TRUE(turnoutCovered) << "the turnouts of the way are drawn reserved";
    EXPECT_TRUE(panel->toolTipOf(tileOf(Block1)).contains(QStringLiteral("reserved for BR 218 Ost")));
    selectGerman();
    EXPECT_EQ(nameShown(AusfahrtOst), QStringLiteral("Ausfahrt Ost · für BR 218 Ost"));
}

TEST_F(TrackPlanAutomationTest, AnUnknownOccupantIsCrossHatchedAndAGhostOnAWayShowsTheFault) {
    setContact(1, true);
    runAutomation({{AutoBr218, 1, End::B}});
    automation->start(std::chrono::milliseconds(0));
    setContact(5, true); // Block 3: nobody can be there
    ASSERT_TRUE(QTest::qWaitFor([&] { return shadeShown(Block3) == BlockShade::Ghost; }, 3000));
    EXPECT_EQ(nameShown(Block3), QStringLiteral("Block 3 · unknown occupant"));
    setContact(5, false);
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown(Block3) == nullptr; }, 3000)) << "free again";

    automation->tick();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shadeShown(Block1) == BlockShade::Reserved; }, 3000));
    setContact(3, true); // Block 1, on BR 218's way
    ASSERT_TRUE(QTest::qWaitFor([&] { return shadeShown(Gleis1) == BlockShade::Fault; }, 3000));
    EXPECT_EQ(nameShown(Gleis1), QStringLiteral("Gleis 1 · BR 218 Ost · fault"));
    EXPECT_EQ(shadeShown(Block1), BlockShade::Ghost);
    painted();
    const TrackPageView* view = panel->pageView(0);
    const QRect room(TrackPageView::Margin, TrackPageView::Margin,
                     view->gridSize().width() * view->tileSize(),
                     view->gridSize().height() * view->tileSize());
    EXPECT_TRUE(room.contains(view->blocks().nameRect(Block1))) << "the name at the page's edge stays on it";
    selectGerman();
    EXPECT_EQ(nameShown(Block1), QStringLiteral("Block 1 · unbekannt belegt"));
    save(QStringLiteral("autoplan-fault-de.png"));
}

TEST_F(TrackPlanAutomationTest, TheBlocksMenuPlacesATrainThroughTheAutomationAndRemovesIt) {
    runAutomation();
    QMenu menu;
    ASSERT_TRUE(panel->fillTileMenu(menu, tileOf(Gleis2)));
    QAction* place = menuAction(menu, QStringLiteral("placeTrainAction"));
    ASSERT_NE(place, nullptr);
    EXPECT_EQ(place->text(), QStringLiteral("Place a train in Gleis 2..."));
    EXPECT_EQ(menuAction(menu, QStringLiteral("removeTrainAction")), nullptr) << "nobody to remove";
    place->trigger();
    auto* dialog = panel->findChild<PlaceTrainDialog*>();
    ASSERT_NE(dialog, nullptr);
    EXPECT_TRUE(dialog->isVisible());
    if (const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR"); !folder.isEmpty())
        dialog->grab().save(folder + QStringLiteral("/autoplan-place-dialog.png"));
    ASSERT_TRUE(dialog->chooseLocomotive(V100));
    dialog->setTowards(End::A);
    dialog->setLengthMm(300);
    dialog->accept();
    const automation::TrainBody* body = automation->dispatcher().tracking().body(V100);
    ASSERT_NE(body, nullptr);
    EXPECT_EQ(body->frontBlock, Gleis2);
    EXPECT_EQ(body->towards, End::A);
    EXPECT_EQ(body->lengthMm, 300);
    EXPECT_EQ(nameShown(Gleis2), QStringLiteral("Gleis 2 · V 100 2023"));

    QMenu again;
    ASSERT_TRUE(panel->fillTileMenu(again, tileOf(Gleis2)));
    QAction* remove = menuAction(again, QStringLiteral("removeTrainAction"));
    ASSERT_NE(remove, nullptr);
    EXPECT_EQ(remove->text(), QStringLiteral("Remove V 100 2023 from Gleis 2"));
    remove->trigger();
    EXPECT_EQ(automation->dispatcher().train(V100), nullptr);
    EXPECT_EQ(shown(Gleis2), nullptr);
}

TEST_F(TrackPlanAutomationTest, APlaceRefusedIsSaidInTheUsersWords) {
    runAutomation({{Ice, 1, End::B}});
    QCoreApplication::processEvents();
    QMenu menu;
    ASSERT_TRUE(panel->fillTileMenu(menu, tileOf(Gleis1)));
    menuAction(menu, QStringLiteral("placeTrainAction"))->trigger();
    auto* dialog = panel->findChild<PlaceTrainDialog*>();
    ASSERT_NE(dialog, nullptr);
    ASSERT_TRUE(dialog->chooseLocomotive(AutoBr218));
    dialog->accept();
    EXPECT_EQ(automation->dispatcher().train(AutoBr218), nullptr);
    EXPECT_EQ(panel->problemText(),
              QStringLiteral("ICE 3 Velaro is in this block already: remove it first."));
}

// A drop on a tile near end a of Gleis 2 places the train facing end a; near end b, facing end b.
TEST_F(TrackPlanAutomationTest, ALocomotiveDroppedOnABlockIsPlacedFacingTheNearerEnd) {
    runAutomation();
    TrackPageView* view = panel->pageView(0);
    ASSERT_TRUE(view->acceptDrops());
    const trackgraph::Block& gleis2 = graph->block(Gleis2);
    for (const End end : {End::A, End::B}) {
        const std::optional<model::TileRef> last = panel->graph()->planTile(gleis2.end(end).tile);
        ASSERT_TRUE(last && last->page == 0);
        std::unique_ptr<QMimeData> data(LocomotiveMime::make(AutoBr218, QStringLiteral("BR 218 Ost")));
        const QPoint point = view->tileRect(last->tile).center();
        QDropEvent drop(QPointF(point), Qt::CopyAction, data.get(), Qt::LeftButton, Qt::NoModifier);
        // Straight to the view: QApplication delivers a drop only while a drag of its own runs.
        static_cast<QObject*>(view)->event(&drop);
        EXPECT_TRUE(drop.isAccepted());
        const automation::TrainBody* body = automation->dispatcher().tracking().body(AutoBr218);
        ASSERT_NE(body, nullptr);
        EXPECT_EQ(body->frontBlock, Gleis2);
        EXPECT_EQ(body->towards, end);
    }
    EXPECT_EQ(nameShown(Gleis2), QStringLiteral("Gleis 2 · BR 218 Ost"));
}

// What the Locomotives list hands a drag: the locomotive's Loc-ID.
TEST_F(TrackPlanAutomationTest, TheLocomotivesListDragsItsLocomotives) {
    LocomotivePanel locomotives;
    locomotives.setRailway(railways.railway());
    LocomotiveFileModel* model = locomotives.model();
    ASSERT_GT(model->rowCount(), 0);
    EXPECT_TRUE(model->flags(model->index(0, 0)) & Qt::ItemIsDragEnabled);
    EXPECT_TRUE(model->mimeTypes().contains(LocomotiveMime::Type));
    QList<std::uint32_t> dragged;
    for (int row = 0; row < model->rowCount(); ++row) {
        std::unique_ptr<QMimeData> data(model->mimeData({model->index(row, 0)}));
        if (const auto locId = LocomotiveMime::locId(data.get()))
            dragged << *locId;
    }
    EXPECT_TRUE(dragged.contains(AutoBr218));
    EXPECT_TRUE(dragged.contains(V100));
}

TEST_F(TrackPlanAutomationTest, TheLegendSaysEveryShadeInWords) {
    runAutomation();
    EXPECT_EQ(panel->blockLegend()->texts(),
              (QStringList{QStringLiteral("free"), QStringLiteral("reserved"), QStringLiteral("train in it"),
                           QStringLiteral("unknown occupant"), QStringLiteral("fault")}));
    EXPECT_TRUE(panel->blockLegend()->toolTip().contains(QStringLiteral("hatched")));
    panel->setShowBlocks(true);
    EXPECT_EQ(shadeShown(Gleis2), BlockShade::Free) << "with Blocks on, free blocks are outlined as free";
    selectGerman();
    EXPECT_EQ(panel->blockLegend()->texts().at(2), QStringLiteral("Zug darin"));
}

// Three trains of the demo run automatically on the simulated station (the test runs the clock): the plan
// names each in its block, shows the ways they reserve, and nobody collides. Screenshots at 1366x768 and
// 1920x1080, English and German, when STELLWERK_SCREENSHOT_DIR names a folder.
TEST_F(TrackPlanAutomationTest, ThreeRunningTrainsAreNamedOnThePlan) {
    std::vector<sim::TrainPlacement> trains = sim::demoPlacements();
    trains.resize(3);
    sim::TrainMovement movement(server.station(), trains);
    movement.start();
    movement.stop(); // the test runs its clock
    railways.railway()->go();
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return railways.railway()->power() == station::PowerState::Running; }, 5000));
    runAutomation(trains);
    automation->start(std::chrono::milliseconds(0));
    bool reservedSeen = false;
    const auto run = [&](int steps) {
        for (int i = 0; i < steps; ++i) {
            movement.advance(std::chrono::milliseconds(50));
            now += 50;
            QTest::qWait(2);
            automation->tick();
            QCoreApplication::processEvents();
            reservedSeen = reservedSeen || !panel->planAutomation().trains().ways().empty();
        }
    };
    run(200); // ten simulated seconds: the trains set off
    EXPECT_TRUE(reservedSeen);
    EXPECT_EQ(movement.accidents().total(), 0);
    for (const std::uint32_t locId : {AutoBr218, Ice, V100}) {
        const automation::TrainBody* body = automation->dispatcher().tracking().body(locId);
        ASSERT_NE(body, nullptr);
        const QString name = panel->planAutomation().trains().block(body->frontBlock).train;
        EXPECT_FALSE(name.isEmpty()) << locId;
        EXPECT_TRUE(nameShown(body->frontBlock).contains(name)) << nameShown(body->frontBlock).toStdString();
    }
    for (const QSize size : {QSize(1366, 768), QSize(1920, 1080)}) {
        panel->resize(size);
        panel->fitToWindow();
        QCoreApplication::processEvents();
        save(QStringLiteral("autoplan-%1-en.png").arg(size.width()));
    }
    selectGerman();
    panel->setShowBlocks(true);
    for (const QSize size : {QSize(1366, 768), QSize(1920, 1080)}) {
        panel->resize(size);
        panel->fitToWindow();
        QCoreApplication::processEvents();
        save(QStringLiteral("autoplan-%1-de.png").arg(size.width()));
    }
}

} // namespace
