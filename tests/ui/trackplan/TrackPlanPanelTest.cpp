#include "trackplan/TrackPlanPanel.h"

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "model/RoutePlan.h"
#include "shell/Translations.h"
#include "support/StationTestSupport.h"
#include "trackplan/PlanGraph.h"
#include "trackplan/TileMenu.h"
#include "trackplan/TileTag.h"
#include "trackplan/TrackColors.h"
#include "trackplan/TrackPageView.h"
#include "trackplan/TrackTileLook.h"

#include <QAction>
#include <QImage>
#include <QLabel>
#include <QMenu>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

constexpr int CommandMs = 5000;

// The track plan on a railway bound to the demo layout's simulated CS2 (without moving trains).
class TrackPlanPanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        ASSERT_TRUE(server.start());
        QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, &panel,
                         &TrackPlanPanel::setRailway);
        panel.setLayoutInUse(&layout);
        station.connectTo(server.url());
        ASSERT_TRUE(test::waitForState(station, State::Ready));
        ASSERT_NE(railways.railway(), nullptr);
        panel.resize(1000, 700);
        panel.show();
    }

    // The first tile of this category on any page.
    std::optional<model::TileRef> firstTile(cs2config::TrackCategory category) const {
        const auto& pages = panel.layout()->pages();
        for (int p = 0; p < int(pages.size()); ++p)
            for (int t = 0; t < int(pages[std::size_t(p)].tiles.size()); ++t)
                if (pages[std::size_t(p)].tiles[std::size_t(t)].category == category)
                    return model::TileRef{p, t};
        return std::nullopt;
    }
    void click(model::TileRef ref) {
        panel.pageTabs()->setCurrentIndex(ref.page);
        TrackPageView* view = panel.pageView(ref.page);
        QTest::mouseClick(view, Qt::LeftButton, {}, view->tileRect(ref.tile).center());
    }

    Translations translations;
    test::TestStation server;
    connection::StationConnection station{support::withEmbeddedStation()};
    model::LayoutInUse layout;
    binding::RailwayBinding railways{station, &layout};
    TrackPlanPanel panel;
};

std::filesystem::path gbertLayoutFolder() {
    return std::filesystem::path(STELLWERK_SHARED_DIR) / "corpus/GBert__railroad/can2udp/files/maerklin";
}

} // namespace

TEST_F(TrackPlanPanelTest, ShowsTheDemoPagesAsTabs) {
    QTabWidget* tabs = panel.pageTabs();
    ASSERT_EQ(tabs->count(), 3);
    EXPECT_EQ(tabs->tabText(0), QStringLiteral("Bahnhof"));
    EXPECT_EQ(tabs->tabText(1), QStringLiteral("Strecke"));
    EXPECT_EQ(tabs->tabText(2), QStringLiteral("Bw"));
    EXPECT_EQ(panel.objectName(), QStringLiteral("trackPlanPanel"));
}

TEST_F(TrackPlanPanelTest, ClickingATurnoutSwitchesItOnceTheStationConfirms) {
    const std::optional<model::TileRef> turnout = firstTile(cs2config::TrackCategory::Turnout);
    ASSERT_TRUE(turnout);
    const int before = panel.lookOf(*turnout).position;
    ASSERT_GE(before, 0);
    const int count =
        railways.railway()->accessory(*panel.layout()->tile(*turnout).accessory)->positionCount();
    QSignalSpy tiles(railways.railway(), &model::Railway::tilesChanged);
    click(*turnout);
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return panel.lookOf(*turnout).position == (before + 1) % count; }, CommandMs));
    ASSERT_GE(tiles.count(), 1);
    EXPECT_TRUE(tiles.last().at(0).value<QList<model::TileRef>>().contains(*turnout));
}

TEST_F(TrackPlanPanelTest, AnS88EventLightsTheContactTile) {
    const std::optional<model::TileRef> contactTile = firstTile(cs2config::TrackCategory::Feedback);
    ASSERT_TRUE(contactTile);
    const model::ContactKey key = *panel.layout()->tile(*contactTile).contact;
    const bool before = panel.lookOf(*contactTile).occupied;
    server.station().setContact(std::uint16_t(key >> 16), std::uint16_t(key & 0xFFFF), !before);
    EXPECT_TRUE(QTest::qWaitFor([&] { return panel.lookOf(*contactTile).occupied == !before; }, CommandMs));
}

namespace {

// Pixels of the occupied colour in the tiles right of a contact's, where only a locomotive's name reaches.
int occupiedBeyond(TrackPageView* view, int tile) {
    const QImage image = view->grab().toImage();
    const QColor occupied = TrackColors::from(view->palette()).occupied;
    const QRect cell = view->tileRect(tile);
    const QRect beyond(cell.right() + 3, cell.top(), cell.width() * 2 - 6, cell.height() / 3);
    int count = 0;
    for (int y = beyond.top(); y <= beyond.bottom(); ++y)
        for (int x = beyond.left(); x <= beyond.right(); ++x)
            count += QColor(image.pixel(QPoint(x, y) * image.devicePixelRatio())) == occupied;
    return count;
}

} // namespace

// The demo's simulator says which train is where (Railway::reportOccupant); the plan names it on the
// occupied contact, and forgets it when the contact is free.
TEST_F(TrackPlanPanelTest, AnOccupiedContactShowsTheNameOfTheLocomotiveOnIt) {
    const std::optional<model::TileRef> contactTile = firstTile(cs2config::TrackCategory::Feedback);
    ASSERT_TRUE(contactTile);
    panel.pageTabs()->setCurrentIndex(contactTile->page);
    TrackPageView* view = panel.pageView(contactTile->page);
    ASSERT_GE(view->tileSize(), TileTag::MinimumTile);
    const model::ContactKey key = *panel.layout()->tile(*contactTile).contact;
    const auto device = std::uint16_t(key >> 16), contact = std::uint16_t(key & 0xFFFF);
    server.station().setContact(device, contact, true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel.lookOf(*contactTile).occupied; }, CommandMs));
    EXPECT_EQ(panel.lookOf(*contactTile).occupant, QString()) << "nobody said which train it is";
    const int before = occupiedBeyond(view, contactTile->tile);

    railways.railway()->reportOccupant(key, 0x4001); // BR 218 Ost in the demo's lokomotive.cs2
    EXPECT_EQ(panel.lookOf(*contactTile).occupant, QStringLiteral("BR 218 Ost"));
    EXPECT_TRUE(panel.toolTipOf(*contactTile).contains(QStringLiteral("Locomotive on it: BR 218 Ost")));
    QTest::qWait(50);
    EXPECT_GT(occupiedBeyond(view, contactTile->tile), before + 20) << "the name runs over the next tiles";

    railways.railway()->reportOccupant(key, 0x7777); // a Loc-ID the station does not know
    EXPECT_EQ(panel.lookOf(*contactTile).occupant, QString());
    railways.railway()->reportOccupant(key, 0x4001);
    server.station().setContact(device, contact, false);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !panel.lookOf(*contactTile).occupied; }, CommandMs));
    EXPECT_EQ(panel.lookOf(*contactTile).occupant, QString()) << "the train left";
    QTest::qWait(50);
    EXPECT_EQ(occupiedBeyond(view, contactTile->tile), 0) << "and its name is gone from the plan";
}

namespace {

QAction* actionNamed(const QMenu& menu, const QString& text) {
    for (QAction* action : menu.actions())
        if (action->text() == text)
            return action;
    return nullptr;
}

} // namespace

// A real station cannot say which train is on a contact: the user can, from the contact's menu.
TEST_F(TrackPlanPanelTest, TheMenuOfAnOccupiedContactSaysWhichLocomotiveIsOnIt) {
    const std::optional<model::TileRef> contactTile = firstTile(cs2config::TrackCategory::Feedback);
    ASSERT_TRUE(contactTile);
    const model::LayoutTile& tile = panel.layout()->tile(*contactTile);
    QMenu free;
    EXPECT_FALSE(TileMenu::fill(free, tile, *railways.railway())) << "a free contact has nobody to name";

    server.station().setContact(std::uint16_t(*tile.contact >> 16), std::uint16_t(*tile.contact & 0xFFFF),
                                true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel.lookOf(*contactTile).occupied; }, CommandMs));
    QMenu menu;
    ASSERT_TRUE(TileMenu::fill(menu, tile, *railways.railway()));
    QAction* unknown = actionNamed(menu, QStringLiteral("Not known"));
    QAction* br218 = actionNamed(menu, QStringLiteral("BR 218 Ost"));
    ASSERT_TRUE(unknown && br218);
    EXPECT_TRUE(unknown->isChecked());
    EXPECT_EQ(menu.actions().size(), 2 + int(railways.railway()->state().locomotives().items().size()))
        << "a heading, 'not known' and every locomotive";
    br218->trigger();
    EXPECT_EQ(panel.lookOf(*contactTile).occupant, QStringLiteral("BR 218 Ost"));

    QMenu again;
    ASSERT_TRUE(TileMenu::fill(again, tile, *railways.railway()));
    EXPECT_TRUE(actionNamed(again, QStringLiteral("BR 218 Ost"))->isChecked());
    actionNamed(again, QStringLiteral("Not known"))->trigger();
    EXPECT_EQ(panel.lookOf(*contactTile).occupant, QString());
}

TEST_F(TrackPlanPanelTest, TheMenuOfATurnoutSwitchesItToThePositionChosen) {
    const std::optional<model::TileRef> turnout = firstTile(cs2config::TrackCategory::Turnout);
    ASSERT_TRUE(turnout);
    const int before = panel.lookOf(*turnout).position;
    QMenu menu;
    ASSERT_TRUE(TileMenu::fill(menu, panel.layout()->tile(*turnout), *railways.railway()));
    ASSERT_GE(menu.actions().size(), 2);
    EXPECT_TRUE(menu.actions().at(before)->isChecked());
    menu.actions().at((before + 1) % 2)->trigger();
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return panel.lookOf(*turnout).position == (before + 1) % 2; }, CommandMs));
}

TEST_F(TrackPlanPanelTest, ClickingARouteButtonRunsTheRouteAndMarksTheButton) {
    const std::optional<model::TileRef> button = firstTile(cs2config::TrackCategory::RouteButton);
    ASSERT_TRUE(button);
    EXPECT_FALSE(panel.lookOf(*button).running);
    QSignalSpy started(railways.railway(), &model::Railway::routeStarted);
    QSignalSpy finished(railways.railway(), &model::Railway::routeFinished);
    click(*button);
    ASSERT_EQ(started.count(), 1);
    EXPECT_EQ(started.first().at(0).toLongLong(), *panel.layout()->tile(*button).route);
    EXPECT_TRUE(panel.lookOf(*button).running);
    EXPECT_TRUE(QTest::qWaitFor([&] { return finished.count() == 1; }, 3 * CommandMs));
    EXPECT_FALSE(panel.lookOf(*button).running);
}

TEST_F(TrackPlanPanelTest, ASetRouteIsDrawnUntilOneOfItsAccessoriesIsThrownElsewhere) {
    const std::optional<model::TileRef> button = firstTile(cs2config::TrackCategory::RouteButton);
    ASSERT_TRUE(button);
    const std::int64_t route = *panel.layout()->tile(*button).route;
    // A turnout tile of an accessory the route switches.
    std::optional<model::TileRef> turnout;
    const model::RoutePlan plan = model::RoutePlan::of(railways.railway()->state().routeFile(), route);
    const std::map<std::int64_t, int> positions = plan.finalPositions();
    const auto& tiles = panel.layout()->pages()[std::size_t(button->page)].tiles;
    for (int t = 0; t < int(tiles.size()) && !turnout; ++t)
        if (tiles[std::size_t(t)].category == cs2config::TrackCategory::Turnout &&
            tiles[std::size_t(t)].accessory && positions.contains(*tiles[std::size_t(t)].accessory))
            turnout = model::TileRef{button->page, t};
    ASSERT_TRUE(turnout) << "the demo's first route throws a turnout of its page";
    const std::int64_t accessory = *panel.layout()->tile(*turnout).accessory;

    QSignalSpy finished(railways.railway(), &model::Railway::routeFinished);
    click(*button);
    ASSERT_TRUE(QTest::qWaitFor([&] { return finished.count() == 1; }, 3 * CommandMs));
    EXPECT_TRUE(QTest::qWaitFor([&] { return panel.lookOf(*button).onRoute; }, CommandMs))
        << "the button is ringed";
    EXPECT_TRUE(panel.lookOf(*turnout).onRoute) << "its turnout is drawn in the route's colour";
    if (const QString dir = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR"); !dir.isEmpty())
        panel.grab().save(dir + QStringLiteral("/track-plan-route-set.png"));

    railways.railway()->switchAccessory(accessory, positions.at(accessory) == 0 ? 1 : 0);
    EXPECT_TRUE(QTest::qWaitFor([&] { return !panel.lookOf(*button).onRoute; }, CommandMs))
        << "thrown elsewhere, the route is no longer set";
    EXPECT_FALSE(panel.lookOf(*turnout).onRoute);
}

TEST_F(TrackPlanPanelTest, ClickingAPageLinkGoesToThatPage) {
    const std::optional<model::TileRef> link = firstTile(cs2config::TrackCategory::PageLink);
    ASSERT_TRUE(link);
    const std::int64_t target = *panel.layout()->tile(*link).page;
    click(*link);
    EXPECT_EQ(panel.layout()->pages()[std::size_t(panel.pageTabs()->currentIndex())].id, target);
}

TEST_F(TrackPlanPanelTest, ATooltipNamesTypeAddressAndName) {
    const std::optional<model::TileRef> turnout = firstTile(cs2config::TrackCategory::Turnout);
    ASSERT_TRUE(turnout);
    const model::LayoutTile& tile = panel.layout()->tile(*turnout);
    const QString text = panel.toolTipOf(*turnout);
    EXPECT_TRUE(text.contains(QStringLiteral("Accessory %1").arg(*tile.accessory))) << text.toStdString();
    EXPECT_TRUE(text.contains(railways.railway()->accessory(*tile.accessory)->name())) << text.toStdString();
}

TEST_F(TrackPlanPanelTest, ExportsTheStationsLayoutAsAFolderThatOpensAgain) {
    QTemporaryDir target;
    ASSERT_TRUE(panel.exportTo(target.path())) << panel.problemText().toStdString();
    for (const char* file : {"gleisbild.cs2", "gleisbilder/Bahnhof.cs2", "gleisbilder/Bw.cs2",
                             "magnetartikel.cs2", "lokomotive.cs2", "fahrstrassen.cs2"})
        EXPECT_TRUE(QFile::exists(target.path() + QStringLiteral("/config/") + QLatin1String(file))) << file;
    ASSERT_TRUE(panel.openFolder(target.path()));
    EXPECT_EQ(panel.pageTabs()->count(), 3);
    EXPECT_EQ(panel.layout()->pages()[0].tiles.size(), railways.railway()->layout().pages()[0].tiles.size());
}

TEST(TrackPlanPanelFiles, OpensACorpusLayoutWithoutAStation) {
    TrackPlanPanel panel;
    ASSERT_TRUE(panel.openFolder(QString::fromStdString(gbertLayoutFolder().string())));
    ASSERT_EQ(panel.pageTabs()->count(), 1);
    EXPECT_EQ(panel.pageTabs()->tabText(0), QStringLiteral("karben"));
    EXPECT_EQ(panel.layout()->pages()[0].tiles.size(), 37U);
}

// karben.cs2 links several tiles to one article and labels tiles with other articles' names: the layout
// check's findings are shown in the problem banner, the first ones in full.
TEST(TrackPlanPanelFiles, TheLayoutChecksFindingsAreShownInTheProblemBanner) {
    TrackPlanPanel panel;
    ASSERT_TRUE(panel.openFolder(QString::fromStdString(gbertLayoutFolder().string())));
    const QString text = panel.problemText();
    EXPECT_TRUE(text.startsWith(QStringLiteral("The layout's files disagree in 13 place(s):")))
        << text.toStdString();
    EXPECT_TRUE(
        text.contains(QStringLiteral("gleisbilder/karben.cs2:16: tile '23' (rechtsweiche at column 5, row 1) "
                                     "and 2 other tiles switch the same article 1 '23'")))
        << text.toStdString();
    EXPECT_TRUE(text.endsWith(QStringLiteral("... and 8 more."))) << text.toStdString();
    panel.showStationPlan();
    EXPECT_EQ(panel.problemText(), QString());
}

TEST(TrackPlanPanelFiles, AConsistentLayoutShowsNoProblem) {
    TrackPlanPanel panel;
    QTemporaryDir folder;
    const std::string index = "[gleisbild]\nseite\n .id=1\n .name=Bahnhof\n";
    const std::string page =
        "[gleisbildseite]\nelement\n .id=0x102\n .typ=rechtsweiche\n .artikel=2\n .text=W1\n";
    const std::string articles = "[magnetartikel]\nartikel\n .id=1\n .name=W1\n .typ=rechtsweiche\n";
    ASSERT_EQ(cs2config::LayoutFolder::write(folder.path().toStdString(), {{"gleisbild.cs2", index},
                                                                           {"gleisbilder/Bahnhof.cs2", page},
                                                                           {"magnetartikel.cs2", articles}}),
              "");
    ASSERT_TRUE(panel.openFolder(folder.path()));
    EXPECT_EQ(panel.pageTabs()->count(), 1);
    EXPECT_EQ(panel.problemText(), QString());
}

TEST(TrackPlanPanelFiles, AMissingFolderIsShownAsAProblemAndKeepsThePlan) {
    TrackPlanPanel panel;
    ASSERT_TRUE(panel.openFolder(QString::fromStdString(gbertLayoutFolder().string())));
    EXPECT_FALSE(panel.openFolder(QStringLiteral("/nonexistent/layout")));
    EXPECT_TRUE(panel.problemText().contains(QStringLiteral("/nonexistent/layout does not exist")))
        << panel.problemText().toStdString();
    EXPECT_EQ(panel.pageTabs()->count(), 1);
}

// Issue 33: the panel shows the layout in use it is given and opens folders into it, so that everything
// reading the layout in use (the command line, the coming automation) sees what the plan shows.
TEST(TrackPlanPanelFiles, OpensFoldersIntoTheLayoutInUseAndShowsItsGraph) {
    model::LayoutInUse layout;
    TrackPlanPanel panel;
    panel.setLayoutInUse(&layout);
    ASSERT_TRUE(panel.openFolder(QStringLiteral(STELLWERK_SOURCE_DIR "/resources/demo-layout")));
    EXPECT_EQ(layout.origin(), model::LayoutInUse::Origin::Folder);
    EXPECT_EQ(panel.layout(), layout.pages().get()) << "the pages of the layout in use, not a copy";
    ASSERT_NE(panel.graph(), nullptr);
    EXPECT_EQ(&panel.graph()->graph(), layout.graph().get()) << "derived once, in the layout in use";
    EXPECT_FALSE(panel.openFolder(QStringLiteral("/nonexistent/layout")));
    EXPECT_EQ(layout.folder().parent_path().filename(), "demo-layout") << "a bad folder changes nothing";

    ASSERT_EQ(layout.open(gbertLayoutFolder()), ""); // opened by someone else
    EXPECT_EQ(panel.layout(), layout.pages().get());
    EXPECT_EQ(panel.pageTabs()->count(), 1);
    EXPECT_EQ(panel.pageTabs()->tabText(0), QStringLiteral("karben"));
}

TEST_F(TrackPlanPanelTest, ShowsTheStationsDownloadAsTheLayoutInUseWithTheRailwaysStates) {
    EXPECT_EQ(layout.origin(), model::LayoutInUse::Origin::Station);
    EXPECT_EQ(panel.layout(), layout.pages().get());
    ASSERT_NE(panel.graph(), nullptr);
    EXPECT_EQ(&panel.graph()->graph(), layout.graph().get());
    EXPECT_EQ(panel.findChild<QLabel*>(QStringLiteral("trackPlanSource"))->text(),
              QStringLiteral("Live from the station"));
}

// Issue 32: a folder whose gleisbild.cs2 is missing was refused, although its pages were there.
TEST(TrackPlanPanelFiles, PagesWithoutTheirIndexAreShownWithAWarning) {
    QTemporaryDir folder;
    const std::string page = "[gleisbildseite]\nelement\n .id=0x102\n .typ=gerade\n";
    ASSERT_EQ(
        cs2config::LayoutFolder::write(folder.path().toStdString(),
                                       {{"gleisbilder/Bw.cs2", page}, {"gleisbilder/Bahnhof.cs2", page}}),
        "");
    TrackPlanPanel panel;
    ASSERT_TRUE(panel.openFolder(folder.path())) << panel.problemText().toStdString();
    ASSERT_EQ(panel.pageTabs()->count(), 2);
    EXPECT_EQ(panel.pageTabs()->tabText(0), QStringLiteral("Bahnhof"));
    EXPECT_EQ(panel.pageTabs()->tabText(1), QStringLiteral("Bw"));
    EXPECT_EQ(panel.layout()->pages()[1].tiles.size(), 1U);
    EXPECT_EQ(
        panel.problemText(),
        folder.filePath(QStringLiteral("config/gleisbild.cs2")) +
            QStringLiteral(" is missing: the 2 page file(s) found in gleisbilder/ are shown in the order of "
                           "their names. Export the layout to write a new gleisbild.cs2 for them."));
}

TEST(TrackPlanPanelFiles, ASinglePageFileOpensAlone) {
    TrackPlanPanel panel;
    ASSERT_TRUE(panel.openFolder(
        QString::fromStdString((gbertLayoutFolder() / "config" / "gleisbilder" / "karben.cs2").string())))
        << panel.problemText().toStdString();
    ASSERT_EQ(panel.pageTabs()->count(), 1);
    EXPECT_EQ(panel.pageTabs()->tabText(0), QStringLiteral("karben"));
    EXPECT_EQ(panel.layout()->pages()[0].tiles.size(), 37U);
}

// The sample layout lists five pages and ships only "5 - Test.cs2": the other tabs say why they are empty.
TEST(TrackPlanPanelFiles, AnEmptyTabOfAMissingPageSaysSoInsideTheTab) {
    const auto sample =
        std::filesystem::path(STELLWERK_SHARED_DIR) / "corpus/bob123456678__TrainControl/cs2_sample_layout";
    TrackPlanPanel panel;
    ASSERT_TRUE(panel.openFolder(QString::fromStdString(sample.string())));
    ASSERT_EQ(panel.pageTabs()->count(), 5);
    auto* notice = panel.pageTabs()->widget(0)->findChild<QLabel*>(QStringLiteral("emptyPageNotice"));
    ASSERT_NE(notice, nullptr);
    EXPECT_EQ(notice->text(),
              QStringLiteral("This page has nothing to show: its file gleisbilder/1 - Main.cs2 is missing."));
    EXPECT_EQ(notice->toolTip(),
              QString::fromStdString((sample / "config/gleisbilder/1 - Main.cs2").string()));
    EXPECT_EQ(panel.pageView(0), nullptr);
    EXPECT_EQ(panel.pageTabs()->widget(4)->findChild<QLabel*>(QStringLiteral("emptyPageNotice")), nullptr);
    ASSERT_NE(panel.pageView(4), nullptr) << "the page that is there is drawn";
    panel.pageTabs()->setCurrentIndex(4);
    EXPECT_GT(panel.tileSize(), 0);
}

// A bar made in English follows a switch to German (the findings' own words stay as the files say them).
TEST(TrackPlanPanelFiles, TheProblemBarFollowsALanguageSwitch) {
    Translations translations;
    ASSERT_TRUE(translations.select(Language::English));
    TrackPlanPanel panel;
    ASSERT_TRUE(panel.openFolder(QString::fromStdString(gbertLayoutFolder().string())));
    ASSERT_TRUE(panel.problemText().startsWith(QStringLiteral("The layout's files disagree in 13 places:")))
        << panel.problemText().toStdString();
    ASSERT_TRUE(translations.select(Language::German));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    EXPECT_TRUE(panel.problemText().startsWith(
        QStringLiteral("Die Dateien des Gleisplans widersprechen sich an 13 Stellen:")))
        << panel.problemText().toStdString();
    EXPECT_TRUE(panel.problemText().endsWith(QStringLiteral("... und 8 weitere.")))
        << panel.problemText().toStdString();
    auto* fold = panel.findChild<QToolButton*>(QStringLiteral("foldProblem"));
    ASSERT_NE(fold, nullptr);
    EXPECT_EQ(fold->text(), QStringLiteral("Alles zeigen")) << "seven lines start folded";
    ASSERT_TRUE(translations.select(Language::English));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    EXPECT_TRUE(panel.problemText().startsWith(QStringLiteral("The layout's files disagree")));
}

// A long problem starts folded to its first line (it would cover most of the plan on a laptop); the user
// unfolds it, folds it again, and dismisses it until the next problem.
TEST(TrackPlanPanelFiles, TheProblemBarFoldsToOneLineAndCanBeDismissed) {
    TrackPlanPanel panel;
    panel.resize(900, 600);
    panel.show();
    ASSERT_TRUE(panel.openFolder(QString::fromStdString(gbertLayoutFolder().string())));
    auto* bar = panel.findChild<QWidget*>(QStringLiteral("trackPlanProblem"));
    auto* text = panel.findChild<QLabel*>(QStringLiteral("problemText"));
    auto* fold = panel.findChild<QToolButton*>(QStringLiteral("foldProblem"));
    auto* dismiss = panel.findChild<QToolButton*>(QStringLiteral("dismissProblem"));
    ASSERT_TRUE(bar && text && fold && dismiss);
    EXPECT_FALSE(text->text().contains(QLatin1Char('\n'))) << "seven lines start folded";
    EXPECT_TRUE(text->text().startsWith(QStringLiteral("The layout's files disagree in 13 place(s):")));
    EXPECT_EQ(fold->text(), QStringLiteral("Show all"));
    EXPECT_EQ(panel.problemText().count(QLatin1Char('\n')), 6) << "folding hides nothing for good";
    const int foldedHeight = bar->sizeHint().height();
    fold->click();
    EXPECT_EQ(text->text().count(QLatin1Char('\n')), 6) << "unfolded: the heading, five findings, the rest";
    EXPECT_GT(bar->sizeHint().height(), 2 * foldedHeight);
    EXPECT_EQ(fold->text(), QStringLiteral("Fold"));
    fold->click();
    EXPECT_FALSE(text->text().contains(QLatin1Char('\n')));
    dismiss->click();
    EXPECT_FALSE(bar->isVisible());
    EXPECT_EQ(panel.problemText(), QString());
    ASSERT_TRUE(panel.openFolder(QString::fromStdString(gbertLayoutFolder().string())));
    EXPECT_TRUE(bar->isVisible()) << "the next problem shows again";
}

// A short problem is shown whole, without a fold button.
TEST(TrackPlanPanelFiles, AShortProblemIsShownWholeWithoutAFoldButton) {
    TrackPlanPanel panel;
    panel.show();
    EXPECT_FALSE(panel.openFolder(QStringLiteral("/nonexistent/layout")));
    auto* fold = panel.findChild<QToolButton*>(QStringLiteral("foldProblem"));
    ASSERT_NE(fold, nullptr);
    EXPECT_FALSE(fold->isVisible());
    EXPECT_EQ(panel.findChild<QLabel*>(QStringLiteral("problemText"))->text(), panel.problemText());
}

TEST(TrackPlanPanelFiles, ExportingWithoutALayoutSaysWhy) {
    TrackPlanPanel panel;
    QTemporaryDir target;
    EXPECT_FALSE(panel.exportTo(target.path()));
    EXPECT_TRUE(panel.problemText().startsWith(QStringLiteral("There is no track plan to export")));
}

TEST(TrackPlanPanelFiles, ZoomChangesTheTileSize) {
    TrackPlanPanel panel;
    ASSERT_TRUE(panel.openFolder(QString::fromStdString(gbertLayoutFolder().string())));
    const int before = panel.tileSize();
    panel.zoomIn();
    EXPECT_GT(panel.tileSize(), before);
    EXPECT_EQ(panel.pageView(0)->tileSize(), panel.tileSize());
    panel.zoomOut();
    panel.zoomOut();
    EXPECT_LT(panel.tileSize(), before);
}

namespace {

// Saves a picture of the panel into $STELLWERK_SCREENSHOT_DIR (for docs/screenshots) when it is set.
void keepScreenshot(const QImage& image, const QString& name) {
    const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
    if (!folder.isEmpty())
        image.save(folder + QLatin1Char('/') + name);
}

// Pixels of the image that are not the most common colour (the page's background).
int drawnPixels(const QImage& image) {
    std::map<QRgb, int> counts;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            ++counts[image.pixel(x, y)];
    int most = 0;
    for (const auto& [colour, count] : counts)
        most = std::max(most, count);
    return image.width() * image.height() - most;
}

} // namespace

TEST_F(TrackPlanPanelTest, TheDemoPlanIsDrawnInLightAndDarkPalettes) {
    panel.fitToWindow();
    const QImage light = panel.grab().toImage();
    EXPECT_GT(drawnPixels(light), 5000);
    keepScreenshot(light, QStringLiteral("track-plan.png"));
    for (int page = 1; page < panel.pageTabs()->count(); ++page) { // the other pages are drawn as well
        panel.pageTabs()->setCurrentIndex(page);
        const QImage other = panel.grab().toImage();
        EXPECT_GT(drawnPixels(other), 5000) << page;
        keepScreenshot(other, QStringLiteral("track-plan-page%1.png").arg(page));
    }
    panel.pageTabs()->setCurrentIndex(0);
    QPalette dark;
    dark.setColor(QPalette::Window, QColor(45, 45, 48));
    dark.setColor(QPalette::WindowText, QColor(225, 225, 225));
    dark.setColor(QPalette::Base, QColor(30, 30, 33));
    dark.setColor(QPalette::Text, QColor(230, 230, 230));
    dark.setColor(QPalette::Button, QColor(60, 60, 64));
    dark.setColor(QPalette::ButtonText, QColor(225, 225, 225));
    panel.setPalette(dark);
    const QImage darkImage = panel.grab().toImage();
    EXPECT_GT(drawnPixels(darkImage), 5000);
    EXPECT_LT(QColor(darkImage.pixel(darkImage.width() / 2, darkImage.height() - 20)).lightness(), 100);
    keepScreenshot(darkImage, QStringLiteral("track-plan-dark.png"));
}

TEST(TrackPlanPanelFiles, DrawsACorpusPage) {
    TrackPlanPanel panel;
    panel.resize(900, 400);
    ASSERT_TRUE(panel.openFolder(QString::fromStdString(gbertLayoutFolder().string())));
    panel.show();
    panel.fitToWindow();
    const QImage image = panel.grab().toImage();
    EXPECT_GT(drawnPixels(image), 3000);
    keepScreenshot(image, QStringLiteral("track-plan-karben.png"));
}
