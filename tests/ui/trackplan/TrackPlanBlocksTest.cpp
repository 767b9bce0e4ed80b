// The track plan with its blocks shown (issue 33): the blocks of the track graph outlined with their names,
// a click on a block's track saying its contacts and ways, and the drawing's problems listed above the plan
// and marked on their tiles, in English and German.
#include "EmbeddedStationSupport.h"
#include "TrackPlanOnDemoStation.h"
#include "binding/RailwayBinding.h"
#include "common/ProblemBar.h"
#include "cs2config/LayoutFolder.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "shell/Translations.h"
#include "stopkeys/EmergencyStopKeys.h"
#include "support/StationTestSupport.h"
#include "trackgraph/TrackGraph.h"
#include "trackplan/BlockOutlines.h"
#include "trackplan/BlockPopup.h"
#include "trackplan/BlockViewSettings.h"
#include "trackplan/GraphProblemText.h"
#include "trackplan/PaintBands.h"
#include "trackplan/PlanGraph.h"
#include "trackplan/TrackColors.h"
#include "trackplan/TrackPageView.h"
#include "trackplan/TrackPlanPanel.h"

#include <QAction>
#include <QApplication>
#include <QImage>
#include <QMenu>
#include <QPainter>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>
#include <set>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

// The track plan on a railway bound to the demo layout's simulated CS2 (without moving trains).
class TrackPlanBlocksTest : public test::TrackPlanOnDemoStation {
protected:
    // The plan tile at a place of a page (by tab name).
    model::TileRef tileAt(const QString& pageName, int column, int row) const {
        const auto& pages = panel->layout()->pages();
        for (int p = 0; p < int(pages.size()); ++p)
            if (pages[std::size_t(p)].name == pageName)
                for (int t = 0; t < int(pages[std::size_t(p)].tiles.size()); ++t) {
                    const auto& position = pages[std::size_t(p)].tiles[std::size_t(t)].position;
                    if (position.column == column && position.row == row)
                        return {p, t};
                }
        ADD_FAILURE() << "no tile at " << pageName.toStdString() << " " << column << "," << row;
        return {};
    }
    TrackPageView* show(int page) {
        panel->pageTabs()->setCurrentIndex(page);
        panel->fitToWindow();
        TrackPageView* view = panel->pageView(page);
        QCoreApplication::processEvents();
        return view;
    }
    void click(model::TileRef ref) {
        TrackPageView* view = show(ref.page);
        QTest::mouseClick(view, Qt::LeftButton, {}, view->tileRect(ref.tile).center());
    }
    // The tile of a demo contact (its number on the station's own bus).
    model::TileRef contactTile(int number) const {
        const auto& pages = panel->layout()->pages();
        for (int p = 0; p < int(pages.size()); ++p)
            for (int t = 0; t < int(pages[std::size_t(p)].tiles.size()); ++t)
                if (const auto& contact = pages[std::size_t(p)].tiles[std::size_t(t)].contact;
                    contact && (*contact & 0xFFFF) == std::uint32_t(number))
                    return {p, t};
        ADD_FAILURE() << "no contact " << number;
        return {};
    }
    void selectGerman() {
        ASSERT_TRUE(translations.select(Language::German));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }
};

} // namespace

namespace {

// Pixels of exactly `colour` inside `area` of the image.
int pixelsOf(const QImage& image, const QRect& area, const QColor& colour) {
    int count = 0;
    const QRect inside = area.intersected(image.rect());
    for (int y = inside.top(); y <= inside.bottom(); ++y)
        for (int x = inside.left(); x <= inside.right(); ++x)
            count += QColor(image.pixel(x, y)) == colour;
    return count;
}

QImage pictureOf(TrackPageView* view) {
    QImage image(view->size(), QImage::Format_ARGB32_Premultiplied);
    view->render(&image);
    return image;
}

// The plan tiles of a page that are drawn and belong to no block, and those of a block.
std::vector<int> tilesOutsideBlocks(const TrackPlanPanel& panel, int page) {
    std::vector<int> tiles;
    const auto& layoutTiles = panel.layout()->pages()[std::size_t(page)].tiles;
    for (int t = 0; t < int(layoutTiles.size()); ++t)
        if (layoutTiles[std::size_t(t)].type != QLatin1String("leer") &&
            panel.graph()->blocksAt({page, t}).empty())
            tiles.push_back(t);
    return tiles;
}

std::vector<int> tilesOfBlock(const TrackPlanPanel& panel, int page, int block) {
    std::vector<int> tiles;
    const auto& layoutTiles = panel.layout()->pages()[std::size_t(page)].tiles;
    for (int t = 0; t < int(layoutTiles.size()); ++t) {
        const std::vector<int> blocks = panel.graph()->blocksAt({page, t});
        if (std::find(blocks.begin(), blocks.end(), block) != blocks.end())
            tiles.push_back(t);
    }
    return tiles;
}

QPalette darkBlockPalette() {
    QPalette dark;
    dark.setColor(QPalette::Window, QColor(45, 45, 48));
    dark.setColor(QPalette::WindowText, QColor(225, 225, 225));
    dark.setColor(QPalette::Base, QColor(30, 30, 33));
    dark.setColor(QPalette::Text, QColor(230, 230, 230));
    dark.setColor(QPalette::Button, QColor(60, 60, 64));
    dark.setColor(QPalette::ButtonText, QColor(225, 225, 225));
    return dark;
}

} // namespace

// The option draws a band in the blocks' colour round the tiles of every block of the page, and that
// colour nowhere on the tiles that are in no block; off, nothing of it.
TEST_F(TrackPlanBlocksTest, TheOptionOutlinesEachBlockOnItsTilesInLightAndDarkPalettes) {
    ASSERT_NE(panel->graph(), nullptr);
    TrackPageView* view = show(0);
    const TrackColors light = TrackColors::from(view->palette());
    EXPECT_TRUE(view->blocks().isEmpty());
    EXPECT_EQ(pixelsOf(pictureOf(view), view->rect(), light.block), 0) << "off: no outline";

    panel->setShowBlocks(true);
    for (const QPalette& palette : {view->palette(), darkBlockPalette()}) {
        panel->setPalette(palette);
        const TrackColors colors = TrackColors::from(view->palette());
        const QImage image = pictureOf(view);
        ASSERT_EQ(view->blocks().blocks().size(), 6U) << "the Bahnhof page holds parts of six blocks";
        for (const BlockOutlines::Block& block : view->blocks().blocks()) {
            const std::vector<int> tiles = tilesOfBlock(*panel, 0, block.id);
            ASSERT_FALSE(tiles.empty());
            for (const int tile : tiles)
                EXPECT_GT(pixelsOf(image, view->tileRect(tile), colors.block), 10)
                    << "block " << block.id << " tile " << tile;
        }
        for (const int tile : tilesOutsideBlocks(*panel, 0))
            EXPECT_EQ(pixelsOf(image, view->tileRect(tile), colors.block), 0) << "tile " << tile;
    }
    EXPECT_NE(TrackColors::from(darkBlockPalette()).block, light.block) << "a lighter violet on a dark plan";

    panel->setShowBlocks(false);
    EXPECT_TRUE(view->blocks().isEmpty());
    EXPECT_EQ(pixelsOf(pictureOf(view), view->rect(), TrackColors::from(view->palette()).block), 0);
}

// Each block's name is on a tab beside its band, in the tab's text colour, over no tile's own name and no
// other block's name.
TEST_F(TrackPlanBlocksTest, TheBlockNamesAreDrawnBesideTheirBlocks) {
    panel->setShowBlocks(true);
    TrackPageView* view = show(0);
    const QImage image = pictureOf(view);
    const TrackColors colors = TrackColors::from(view->palette());
    std::set<QString> names;
    std::vector<QRect> tabs;
    for (const BlockOutlines::Block& block : view->blocks().blocks()) {
        names.insert(block.name);
        const QRect tab = view->blocks().nameRect(block.id);
        ASSERT_FALSE(tab.isEmpty()) << block.name.toStdString();
        const int tile = view->tileSize();
        EXPECT_TRUE(tab.intersects(view->blocks().bandRect(block.id).adjusted(-tile, -tile, tile, tile)));
        EXPECT_GT(pixelsOf(image, tab, colors.blockText), 10) << "the name's letters";
        EXPECT_GT(pixelsOf(image, tab, colors.block), tab.width() * tab.height() / 3) << "on its tab";
        for (int t = 0; t < int(panel->layout()->pages()[0].tiles.size()); ++t)
            if (const TileTag tag = view->tagOf(t); tag.shown()) {
                EXPECT_FALSE(tab.intersects(tag.rect())) << block.name.toStdString() << " over " << t;
            }
        for (const QRect& other : tabs)
            EXPECT_FALSE(tab.intersects(other)) << block.name.toStdString();
        tabs.push_back(tab);
    }
    EXPECT_EQ(names, (std::set<QString>{QStringLiteral("Gleis 1"), QStringLiteral("Gleis 2"),
                                        QStringLiteral("Abstellgleis"), QStringLiteral("Einfahrt West"),
                                        QStringLiteral("Ausfahrt Ost"), QStringLiteral("Block 1")}));
}

// A click on the contact of "Gleis 1" says its contacts, its signal and where each end leads, over which
// turnout in which position; in German too.
TEST_F(TrackPlanBlocksTest, AClickOnABlocksContactListsItsContactsAndWays) {
    panel->setShowBlocks(true);
    click(contactTile(1));
    ASSERT_TRUE(panel->blockPopup()->isVisible());
    const QString text = panel->blockPopup()->plainText();
    for (const char* words :
         {"Block 4 'Gleis 1'", "7 tiles, 1260 mm", "Contact 1 'Gleis 1'",
          "Signal 'P1', for trains towards end b", "From end a (page 'Bahnhof', column 5, row 5):",
          "to block 3 'Einfahrt West', end a, over turnout 1 'W1 Einfahrt West' straight, set by route "
          "'Einfahrt Gleis 1'",
          "From end b (page 'Bahnhof', column 11, row 5):",
          "to block 5 'Ausfahrt Ost', end a, over turnout 2 'W2 Ausfahrt Ost' straight, set by route "
          "'Ausfahrt Gleis 1'"})
        EXPECT_TRUE(text.contains(QLatin1String(words))) << words << "\n" << text.toStdString();
    panel->blockPopup()->hide();

    selectGerman();
    click(contactTile(1));
    const QString german = panel->blockPopup()->plainText();
    for (const char* words :
         {"Block 4 „Gleis 1“", "7 Felder, 1260 mm", "Kontakt 1 „Gleis 1“",
          "Signal „P1“, für Züge in Richtung Ende b", "Von Ende a (Seite „Bahnhof“, Spalte 5, Zeile 5):",
          "nach Block 3 „Einfahrt West“, Ende a, über Weiche 1 „W1 Einfahrt West“ gerade, "
          "gestellt von Fahrstraße „Einfahrt Gleis 1“"})
        EXPECT_TRUE(german.contains(QString::fromUtf8(words))) << words << "\n" << german.toStdString();
}

// Where blocks meet with no turnout, and where three ways leave over turnouts and a buffer stop ends one.
TEST_F(TrackPlanBlocksTest, TheWaysOfABlockNameEveryTurnoutPositionAndTheTrackEnds) {
    panel->setShowBlocks(true);
    ASSERT_TRUE(panel->showBlockAt(contactTile(8))); // Ausfahrt Ost: W2 on one side, W3 on the other
    const QString text = panel->blockPopup()->plainText();
    for (const char* words : {"to block 1 'Gleis 2', end b, over turnout 2 'W2 Ausfahrt Ost' diverging",
                              "to block 4 'Gleis 1', end b, over turnout 2 'W2 Ausfahrt Ost' straight",
                              "to block 2 'Abstellgleis', end a, over turnout 3", "diverging",
                              "to block 6 'Block 1', end a, over turnout 3"})
        EXPECT_TRUE(text.contains(QLatin1String(words))) << words << "\n" << text.toStdString();
    ASSERT_TRUE(panel->showBlockAt(contactTile(4))); // Block 2 between Block 1 and Block 3 on the line
    EXPECT_TRUE(
        panel->blockPopup()->plainText().contains(QStringLiteral("to block 6 'Block 1', end b, directly")))
        << panel->blockPopup()->plainText().toStdString();
}

// With the blocks shown a turnout still switches at a click, and opens no popup; without them a click on a
// block's track opens nothing.
TEST_F(TrackPlanBlocksTest, AClickOnATurnoutStillSwitchesItAndTheOptionOffOpensNothing) {
    panel->setShowBlocks(true);
    const model::TileRef turnout = tileAt(QStringLiteral("Bahnhof"), 4, 5);
    ASSERT_TRUE(panel->layout()->tile(turnout).accessory);
    const int before = panel->lookOf(turnout).position;
    ASSERT_GE(before, 0);
    click(turnout);
    EXPECT_FALSE(panel->blockPopup()->isVisible());
    EXPECT_TRUE(QTest::qWaitFor([&] { return panel->lookOf(turnout).position == (before + 1) % 2; }, 5000));

    panel->setShowBlocks(false);
    click(contactTile(1));
    EXPECT_FALSE(panel->blockPopup()->isVisible());
}

// The right click's menu offers the block beside the contact's locomotives, and opens the same popup.
TEST_F(TrackPlanBlocksTest, TheTileMenuOffersTheBlock) {
    QMenu off;
    EXPECT_FALSE(panel->fillTileMenu(off, contactTile(1))) << "a free contact, blocks not shown: nothing";
    panel->setShowBlocks(true);
    show(0);
    QMenu menu;
    ASSERT_TRUE(panel->fillTileMenu(menu, contactTile(1)));
    QAction* entry = menu.findChild<QAction*>(QStringLiteral("blockEntry"));
    ASSERT_NE(entry, nullptr);
    EXPECT_EQ(entry->text(), QStringLiteral("Block 4 'Gleis 1'..."));
    entry->trigger();
    EXPECT_TRUE(panel->blockPopup()->isVisible());
    EXPECT_TRUE(panel->blockPopup()->plainText().startsWith(QStringLiteral("Block 4 'Gleis 1'")));
}

// The demo's Bw page has three depot tracks without a contact: the amber bar above the plan lists them with
// their places, in English and in German after a switch.
TEST_F(TrackPlanBlocksTest, TheProblemsBarListsTheDemosProblemsInEnglishAndGerman) {
    ProblemBar* bar = panel->drawingProblemBar();
    EXPECT_EQ(bar->text(), QString()) << "blocks not shown";
    panel->setShowBlocks(true);
    EXPECT_TRUE(bar->isVisible());
    const QString sentence = QStringLiteral(
        "The track from here to the next turnout or end has no contact, so a train there cannot be seen; add "
        "a contact where trains may stop.");
    EXPECT_EQ(bar->text(), QStringLiteral("The drawing of the track plan has 3 problems:\n") +
                               QStringLiteral("Page 'Bw', column 3, row 1: ") + sentence + QLatin1Char('\n') +
                               QStringLiteral("Page 'Bw', column 4, row 2: ") + sentence + QLatin1Char('\n') +
                               QStringLiteral("Page 'Bw', column 3, row 3: ") + sentence);
    EXPECT_TRUE(bar->isFolded()) << "four lines start folded";
    EXPECT_EQ(panel->problemText(), QString()) << "the file problems' bar stays hidden";
    const QImage picture = bar->grab().toImage();
    EXPECT_EQ(QColor(picture.pixel(picture.width() / 2, 2)), QColor(0xf2, 0xb2, 0x33)) << "amber, not red";

    selectGerman();
    EXPECT_TRUE(bar->text().startsWith(QStringLiteral("Die Zeichnung des Gleisplans hat 3 Probleme:\n"
                                                      "Seite „Bw“, Spalte 3, Zeile 1: Das Gleis von hier")))
        << bar->text().toStdString();
    EXPECT_FALSE(bar->text().contains(QStringLiteral("contact"))) << bar->text().toStdString();
    panel->setShowBlocks(false);
    EXPECT_EQ(bar->text(), QString());
}

// The three tiles the problems are on carry an amber marker, and their tooltip says the problem; no other
// tile has one.
TEST_F(TrackPlanBlocksTest, TheProblemTilesAreMarkedAndTheirTooltipSaysWhy) {
    panel->setShowBlocks(true);
    TrackPageView* view = show(2);
    const std::vector<int> expected{tileAt(QStringLiteral("Bw"), 3, 1).tile,
                                    tileAt(QStringLiteral("Bw"), 4, 2).tile,
                                    tileAt(QStringLiteral("Bw"), 3, 3).tile};
    EXPECT_EQ(std::set<int>(view->problemTiles().begin(), view->problemTiles().end()),
              std::set<int>(expected.begin(), expected.end()));
    const QImage image = pictureOf(view);
    const QColor amber = TrackColors::from(view->palette()).problem;
    for (int t = 0; t < int(panel->layout()->pages()[2].tiles.size()); ++t) {
        const bool marked = std::find(expected.begin(), expected.end(), t) != expected.end();
        const int pixels = pixelsOf(image, view->problemMarkerRect(t), amber);
        EXPECT_EQ(pixels > 20, marked) << "tile " << t << ": " << pixels;
        EXPECT_EQ(panel->toolTipOf({2, t}).contains(QStringLiteral("Problem: The track from here")), marked)
            << t;
    }
    EXPECT_TRUE(panel->pageView(0)->problemTiles().empty()) << "the Bahnhof page has none";
    panel->setShowBlocks(false);
    EXPECT_TRUE(view->problemTiles().empty());
    EXPECT_FALSE(panel->toolTipOf({2, expected[0]}).contains(QStringLiteral("Problem")));
}

// The choice is kept: a plan made later shows the blocks at once.
TEST_F(TrackPlanBlocksTest, TheOptionIsRemembered) {
    EXPECT_FALSE(panel->blocksAction()->isChecked());
    panel->blocksAction()->trigger();
    EXPECT_TRUE(panel->showsBlocks());
    EXPECT_TRUE(BlockViewSettings::shown());
    TrackPlanPanel later;
    EXPECT_TRUE(later.showsBlocks());
    EXPECT_TRUE(later.blocksAction()->isChecked());
    panel->blocksAction()->trigger();
    EXPECT_FALSE(BlockViewSettings::shown());
    EXPECT_FALSE(TrackPlanPanel().showsBlocks());
}

// The graph is derived when a layout is shown, not when the plan is painted, zoomed or the option changes.
TEST_F(TrackPlanBlocksTest, TheGraphIsDerivedOncePerLayout) {
    const PlanGraph* graph = panel->graph();
    ASSERT_NE(graph, nullptr);
    EXPECT_EQ(graph->graph().blocks().size(), 9U);
    panel->setShowBlocks(true);
    TrackPageView* view = show(1);
    pictureOf(view);
    panel->zoomIn();
    pictureOf(view);
    panel->setShowBlocks(false);
    panel->setShowBlocks(true);
    EXPECT_EQ(panel->graph(), graph);
    QTemporaryDir folder;
    ASSERT_TRUE(panel->exportTo(folder.path()));
    ASSERT_TRUE(panel->openFolder(folder.path()));
    EXPECT_NE(panel->graph(), graph) << "another layout, another graph";
}

// A plan opened from a folder without a station shows its blocks as well, with the route names of its
// fahrstrassen.cs2 and the article names of its magnetartikel.cs2.
TEST(TrackPlanBlocksFiles, AnOpenedFolderShowsItsBlocksWithTheNamesOfItsFiles) {
    Translations translations;
    ASSERT_TRUE(translations.select(Language::English));
    BlockViewSettings::setShown(true);
    TrackPlanPanel panel;
    panel.resize(1000, 620);
    panel.show();
    ASSERT_TRUE(panel.openFolder(QStringLiteral(STELLWERK_SOURCE_DIR "/resources/demo-layout")));
    BlockViewSettings::setShown(false);
    ASSERT_NE(panel.graph(), nullptr);
    EXPECT_EQ(panel.graph()->graph().blocks().size(), 9U);
    ASSERT_NE(panel.pageView(1), nullptr);
    EXPECT_EQ(panel.pageView(1)->blocks().blocks().size(), 5U) << "the Strecke page";
    EXPECT_EQ(panel.drawingProblemBar()->text().count(QLatin1Char('\n')), 3);
    const auto& tiles = panel.layout()->pages()[0].tiles;
    for (int t = 0; t < int(tiles.size()); ++t)
        if (tiles[std::size_t(t)].contact && (*tiles[std::size_t(t)].contact & 0xFFFF) == 1) {
            ASSERT_TRUE(panel.showBlockAt({0, t}));
        }
    EXPECT_TRUE(panel.blockPopup()->plainText().contains(
        QStringLiteral("over turnout 1 'W1 Einfahrt West' straight, set by route 'Einfahrt Gleis 1'")))
        << panel.blockPopup()->plainText().toStdString();
}

namespace {

// The panel with the block popup drawn where it stands on the screen.
QImage withPopup(TrackPlanPanel& panel) {
    QImage image = panel.grab().toImage();
    if (BlockPopup* popup = panel.blockPopup(); popup->isVisible()) {
        QPainter painter(&image);
        painter.drawPixmap(panel.mapFromGlobal(popup->pos()), popup->grab());
    }
    return image;
}

} // namespace

// Pictures for the guide (docs/screenshots, when STELLWERK_SCREENSHOT_DIR is set): the demo's station with
// its blocks and the popup of "Gleis 1", in English and German; the popup fits beside the tile it was asked
// from and shows every line of the block.
TEST_F(TrackPlanBlocksTest, ScreenshotsOfTheBlocksInEnglishAndGerman) {
    panel->setShowBlocks(true);
    panel->resize(1000, 760); // the plan's part of a 1366 x 768 desk is smaller; the popup needs the room
    const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
    for (const char* name : {"track-plan-blocks.png", "track-plan-blocks-de.png"}) {
        if (QLatin1String(name).contains(QLatin1String("-de")))
            selectGerman();
        click(contactTile(1));
        BlockPopup* popup = panel->blockPopup();
        ASSERT_TRUE(popup->isVisible());
        EXPECT_LE(popup->width(), 520) << "a popup, not a page";
        EXPECT_EQ(popup->sizeHint().height(), popup->height()) << "every line shown";
        const QImage image = withPopup(*panel);
        if (!folder.isEmpty())
            image.save(folder + QLatin1Char('/') + QLatin1String(name));
        popup->hide();
    }
}

// Painted on all cores or by one painter, the bands, names and markers come out the same.
TEST_F(TrackPlanBlocksTest, BlocksPaintTheSameInBandsAsInOnePainter) {
    panel->setShowBlocks(true);
    for (const int page : {0, 2}) {
        TrackPageView* view = show(page);
        const QImage bands = pictureOf(view);
        PaintBands::setEnabled(false);
        const QImage one = pictureOf(view);
        PaintBands::setEnabled(true);
        EXPECT_TRUE(bands == one) << "page " << page;
    }
}

// Every kind of problem is said in German in the German plan (the graph's own sentences are English).
TEST(GraphProblemTextTest, EveryKindOfProblemHasItsOwnGermanSentence) {
    Translations translations;
    const cs2config::LayoutFolder::Content demo =
        cs2config::LayoutFolder::open(STELLWERK_SOURCE_DIR "/resources/demo-layout");
    const trackgraph::TrackGraph graph = trackgraph::TrackGraph::derive(demo.layout);
    ASSERT_GT(graph.tiles().size(), 10U);
    std::set<QString> english;
    std::set<QString> german;
    for (int kind = 0; kind <= int(trackgraph::ProblemKind::TooManyWays); ++kind) {
        const trackgraph::Problem problem{trackgraph::ProblemKind(kind), 5, {}};
        ASSERT_TRUE(translations.select(Language::English));
        const QString inEnglish = GraphProblemText::of(graph, problem);
        ASSERT_TRUE(translations.select(Language::German));
        const QString inGerman = GraphProblemText::of(graph, problem);
        EXPECT_TRUE(inGerman.startsWith(QStringLiteral("Seite „Bahnhof“, Spalte"))) << inGerman.toStdString();
        EXPECT_NE(inGerman, inEnglish) << kind;
        english.insert(inEnglish);
        german.insert(inGerman);
    }
    EXPECT_EQ(english.size(), std::size_t(trackgraph::ProblemKind::TooManyWays) + 1) << "a sentence per kind";
    EXPECT_EQ(german.size(), english.size());
    ASSERT_TRUE(translations.select(Language::English));
}

// The popup takes the keys while it is open: Escape closes it (and stops nothing), Space still stops the
// layout as everywhere else.
TEST_F(TrackPlanBlocksTest, WithThePopupOpenEscapeClosesItAndSpaceStillStops) {
    EmergencyStopKeys stopKeys(panel.get());
    QSignalSpy stops(&stopKeys, &EmergencyStopKeys::stopRequested);
    panel->setShowBlocks(true);
    click(contactTile(1));
    BlockPopup* popup = panel->blockPopup();
    ASSERT_TRUE(popup->isVisible());
    ASSERT_EQ(QApplication::activePopupWidget(), popup);
    QTest::keyClick(QApplication::activePopupWidget(), Qt::Key_Space);
    EXPECT_EQ(stops.count(), 1) << "Space stops the layout with the popup open";
    QTest::keyClick(QApplication::activePopupWidget(), Qt::Key_Escape);
    EXPECT_FALSE(popup->isVisible());
    EXPECT_EQ(stops.count(), 1) << "Escape only closed the popup";
}
