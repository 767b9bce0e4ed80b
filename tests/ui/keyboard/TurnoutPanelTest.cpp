// The turnout panel against the demo layout's simulated CS2 over loopback TCP: the keyboard's articles
// on their pages, switching them (and numbers without an article) on the station, and changes made by
// another controller.

#include "keyboard/TurnoutPanel.h"

#include "common/Contrast.h"
#include "keyboard/TurnoutKey.h"
#include "support/KeyboardTestSupport.h"

#include <QComboBox>
#include <QImage>
#include <QLabel>
#include <QMenu>
#include <QToolButton>
#include <algorithm>
#include <gtest/gtest.h>
#include <map>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

// The demo keyboard: W1 left turnout (1), W2 right turnout (2), W4 three-way turnout (4 and 5), F
// semaphore Hp0/Hp1/Hp2 (9 and 10); 14 to 16 have no article.
constexpr std::uint32_t Mm2Accessory1 = 0x3000;

class TurnoutPanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(demo.start());
        ASSERT_TRUE(controller.connect(demo.url()));
        QObject::connect(&controller.railways, &binding::RailwayBinding::railwayChanged, &panel,
                         &TurnoutPanel::setRailway);
        panel.setRailway(controller.railway());
        panel.resize(760, 700);
        panel.show();
    }

    TurnoutKey& key(std::int64_t address) const {
        TurnoutKey* found = panel.keyFor(address);
        if (!found)
            throw std::runtime_error("address not on the current page");
        return *found;
    }
    std::optional<std::uint8_t> stationPosition(std::int64_t address) {
        return demo.station().accessoryPosition(Mm2Accessory1 + std::uint32_t(address) - 1);
    }
    static QStringList buttonTexts(const TurnoutKey& key) {
        QStringList texts;
        for (const QToolButton* button : key.positionButtons())
            texts << button->text();
        return texts;
    }
    static QList<QAction*> positionActions(const TurnoutKey& key) {
        return key.positionMenuButton() ? key.positionMenuButton()->menu()->actions() : QList<QAction*>{};
    }
    static QStringList menuTexts(const TurnoutKey& key) {
        QStringList texts;
        for (const QAction* action : positionActions(key))
            texts << action->text();
        return texts;
    }

    test::DemoStation demo;
    test::Controller controller;
    TurnoutPanel panel;
};

TEST_F(TurnoutPanelTest, TheDemoArticlesAppearOnPageOneWithNamesAndAddresses) {
    EXPECT_EQ(panel.objectName(), QStringLiteral("turnoutPanel"));
    EXPECT_EQ(panel.page(), 0);
    ASSERT_EQ(panel.keys().size(), 16);
    EXPECT_EQ(panel.keys().first()->address(), 1);
    EXPECT_EQ(panel.keys().last()->address(), 16);
    EXPECT_EQ(key(1).face().name, QStringLiteral("W1 Einfahrt West"));
    EXPECT_EQ(key(1).face().kind, AccessoryIcon::Kind::LeftTurnout);
    EXPECT_EQ(key(1).positionText(), QStringLiteral("Straight"));
    EXPECT_TRUE(key(1).toggles());
    EXPECT_EQ(key(2).face().kind, AccessoryIcon::Kind::RightTurnout);
    EXPECT_EQ(key(4).face().name, QStringLiteral("W4 Bw"));
    EXPECT_EQ(menuTexts(key(4)), (QStringList{"Left", "Straight", "Right"}));
    EXPECT_TRUE(key(4).positionButtons().isEmpty()) << "three buttons would not fit on a key";
    EXPECT_EQ(key(5).face().role, KeyFace::Role::PartOfArticle);
    EXPECT_EQ(key(5).positionText(), QStringLiteral("part of 4"));
    EXPECT_EQ(key(9).face().kind, AccessoryIcon::Kind::Semaphore);
    EXPECT_EQ(menuTexts(key(9)), (QStringList{"Hp0", "Hp1", "Hp2"}));
    EXPECT_EQ(key(9).positionMenuButton()->text(), key(9).positionText()) << "named after the position";
    EXPECT_EQ(key(13).face().kind, AccessoryIcon::Kind::ShuntSignal);
    EXPECT_EQ(key(15).face().role, KeyFace::Role::Address);
    EXPECT_EQ(buttonTexts(key(15)), (QStringList{"Red", "Green"}));
    EXPECT_EQ(key(15).positionButtons().first()->toolButtonStyle(), Qt::ToolButtonIconOnly);
    EXPECT_EQ(key(15).positionButtons().first()->toolTip(), QStringLiteral("Switch 15 to Red"));
}

TEST(TurnoutPanel, WithoutAStationItSaysSoInsteadOfShowingKeys) {
    TurnoutPanel empty;
    empty.show();
    auto* text = empty.findChild<QLabel*>(QStringLiteral("turnoutPanelEmpty"));
    ASSERT_NE(text, nullptr);
    EXPECT_TRUE(text->isVisible());
    EXPECT_FALSE(empty.keys().first()->isVisible());
    EXPECT_FALSE(empty.findChild<QToolButton*>(QStringLiteral("nextPage"))->isEnabled());
}

TEST_F(TurnoutPanelTest, ClickingATurnoutSwitchesItOnTheStation) {
    ASSERT_EQ(controller.railway()->accessory(1)->position(), 1);
    test::Controller observer;
    ASSERT_TRUE(observer.connect(demo.url()));
    QTest::mouseClick(&key(1), Qt::LeftButton);
    EXPECT_TRUE(key(1).pending()) << "marked until the station confirms";
    ASSERT_TRUE(QTest::qWaitFor([&] { return stationPosition(1) == 0; }, test::CommandMs));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !key(1).pending(); }, test::CommandMs));
    EXPECT_FALSE(key(1).unconfirmed());
    EXPECT_EQ(key(1).positionText(), QStringLiteral("Diverging"));
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return observer.railway()->accessory(1)->position() == 0; }, test::CommandMs))
        << "another controller sees the new position";
}

TEST_F(TurnoutPanelTest, EnterSwitchesTheFocusedKey) {
    key(3).setFocus();
    QTest::keyClick(&key(3), Qt::Key_Return);
    EXPECT_TRUE(QTest::qWaitFor([&] { return stationPosition(3) == 0 && key(3).face().position == 0; },
                                test::CommandMs));
}

TEST_F(TurnoutPanelTest, AThreeWayTurnoutOffersItsPositions) {
    positionActions(key(4)).at(2)->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return controller.railway()->accessory(4)->position() == 2; },
                                test::CommandMs));
    EXPECT_EQ(stationPosition(5), 0) << "right is the second address's red output";
    ASSERT_TRUE(QTest::qWaitFor([&] { return positionActions(key(4)).at(2)->isChecked(); }, test::CommandMs));
    EXPECT_FALSE(positionActions(key(4)).at(1)->isChecked());
    EXPECT_EQ(key(4).positionMenuButton()->text(), QStringLiteral("Right"));
}

TEST_F(TurnoutPanelTest, AnAddressWithoutArticleSwitches) {
    QTest::mouseClick(key(15).positionButtons().at(1), Qt::LeftButton);
    ASSERT_TRUE(QTest::qWaitFor([&] { return stationPosition(15) == 1; }, test::CommandMs));
    ASSERT_TRUE(QTest::qWaitFor([&] { return key(15).face().position == 1; }, test::CommandMs));
    EXPECT_TRUE(key(15).positionButtons().at(1)->isChecked());
    EXPECT_EQ(key(15).positionText(), QStringLiteral("Green"));
    QTest::mouseClick(key(15).positionButtons().at(0), Qt::LeftButton);
    EXPECT_TRUE(QTest::qWaitFor([&] { return stationPosition(15) == 0 && key(15).face().position == 0; },
                                test::CommandMs));
}

TEST_F(TurnoutPanelTest, PageNavigationShowsTheNextSixteenAddresses) {
    EXPECT_EQ(panel.pageCount(), TurnoutPanel::MinimumPages);
    QTest::mouseClick(panel.findChild<QToolButton*>(QStringLiteral("nextPage")), Qt::LeftButton);
    EXPECT_EQ(panel.page(), 1);
    EXPECT_EQ(panel.keys().first()->address(), 17);
    EXPECT_EQ(panel.keys().last()->address(), 32);
    EXPECT_EQ(panel.keys().first()->face().role, KeyFace::Role::Address);
    EXPECT_EQ(panel.keyFor(1), nullptr);
    QTest::keyClick(&panel, Qt::Key_PageDown);
    EXPECT_EQ(panel.keys().first()->address(), 33);
    QTest::keyClick(panel.keys().first(), Qt::Key_PageUp);
    EXPECT_EQ(panel.page(), 1) << "one page per key press, also from a key";
    QTest::keyClick(&panel, Qt::Key_PageUp);
    EXPECT_EQ(panel.page(), 0);
    EXPECT_EQ(panel.keys().first()->face().name, QStringLiteral("W1 Einfahrt West"));
    auto* picker = panel.findChild<QComboBox*>(QStringLiteral("pagePicker"));
    ASSERT_EQ(picker->count(), TurnoutPanel::MinimumPages);
    EXPECT_EQ(picker->itemText(1), QStringLiteral("Page 2: 17–32"));
    picker->activated(19);
    EXPECT_EQ(panel.keys().last()->address(), 320);
}

TEST_F(TurnoutPanelTest, AChangeMadeByAnotherControllerShowsUp) {
    test::Controller other;
    ASSERT_TRUE(other.connect(demo.url()));
    ASSERT_EQ(key(2).positionText(), QStringLiteral("Straight"));
    other.railway()->switchAccessory(2, 0);
    EXPECT_TRUE(QTest::qWaitFor([&] { return key(2).positionText() == QStringLiteral("Diverging"); },
                                test::CommandMs));
    EXPECT_FALSE(key(2).pending());
    other.railway()->switchAddress(16, 1);
    EXPECT_TRUE(QTest::qWaitFor([&] { return key(16).face().position == 1; }, test::CommandMs));
}

TEST_F(TurnoutPanelTest, ASwitchingTheStationDoesNotConfirmIsMarked) {
    demo.stop();
    QTest::mouseClick(&key(2), Qt::LeftButton);
    EXPECT_TRUE(key(2).pending());
    ASSERT_TRUE(QTest::qWaitFor([&] { return !key(2).pending(); }, test::CommandMs));
    EXPECT_TRUE(key(2).unconfirmed());
    EXPECT_TRUE(key(2).toolTip().contains(QStringLiteral("did not confirm")))
        << key(2).toolTip().toStdString();
    EXPECT_EQ(key(2).positionText(), QStringLiteral("Straight")) << "the position the station last confirmed";
}

} // namespace

namespace {

// The strongest contrast against the key's face within rows [from, to) of the key (fractions of its height).
double strongestContrast(const QImage& key, double from, double to) {
    const QColor face = key.pixelColor(key.width() / 2, 8);
    double strongest = 1.0;
    for (int y = int(from * key.height()); y < int(to * key.height()); ++y)
        for (int x = 6; x < key.width() - 6; ++x)
            strongest = std::max(strongest, Contrast::ratio(key.pixelColor(x, y), face));
    return strongest;
}

} // namespace

// Issue 32: greyed (not reported) keys showed their names at about 1.5:1 while a signal's drawing stayed
// darker than anything else on the key. Greyed keys are paler than usable ones, yet readable.
TEST_F(TurnoutPanelTest, GreyedKeysArePalerYetReadable) {
    constexpr double Drawing = 0.15, Texts = 0.7; // the drawing's and the texts' rows
    QTest::qWait(20);
    std::map<int, std::pair<double, double>> usable; // key -> drawing, texts
    for (const int address : {1, 6}) {
        const QImage image = key(address).grab().toImage();
        usable[address] = {strongestContrast(image, Drawing, 0.55), strongestContrast(image, Texts, 0.98)};
    }
    demo.stop();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !controller.railway()->isStateReported(); }, test::CommandMs));
    for (const int address : {1, 6}) {
        ASSERT_FALSE(key(address).isEnabled());
        const QImage image = key(address).grab().toImage();
        const double drawing = strongestContrast(image, Drawing, 0.55);
        const double texts = strongestContrast(image, Texts, 0.98);
        EXPECT_GE(texts, Contrast::ForText) << "key " << address;
        EXPECT_LT(texts, usable[address].second) << "key " << address;
        EXPECT_GE(drawing, Contrast::ForDrawings) << "key " << address;
        EXPECT_LT(drawing, usable[address].first) << "key " << address;
        EXPECT_LT(drawing, texts + 1.0)
            << "key " << address << ": the drawing is not the darkest thing on it";
    }
}
