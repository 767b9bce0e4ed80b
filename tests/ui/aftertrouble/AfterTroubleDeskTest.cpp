// Issue 32 on the desk: a station that stalls while a throttle gives a speed, and wakes. The station ends
// where the desk last showed it, the status bar says what was brought back until the person dismisses it,
// and Station → "Bring the layout back in step" and "After a failed command" do what they say.

#include "aftertrouble/AftermathMenu.h"
#include "aftertrouble/AftermathSettings.h"
#include "aftertrouble/CorrectionNotice.h"
#include "shell/PassingMessage.h"
#include "support/TrustTestSupport.h"

#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSignalSpy>

namespace stellwerk::ui::test {
namespace {

constexpr std::uint32_t Br218 = 0x4001; // a locomotive of the demo layout
constexpr std::uint32_t V100 = 0x0018;

class AfterTroubleOnTheDesk : public DeskOnTestStation {
protected:
    int stationSpeed(std::uint32_t loco) {
        const sim::SimulatedLoco* found = server.station().loco(loco);
        return found ? found->speed : -1;
    }
    bool drive(std::uint32_t loco, int speed) {
        railway()->setSpeed(loco, speed);
        return QTest::qWaitFor([&] { return railway()->locomotive(loco)->speed() == speed; }, CommandMs);
    }
    // For docs/screenshots: the desk with the notice, in English and German, when STELLWERK_SCREENSHOT_DIR is
    // set.
    void saveScreenshots() {
        const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
        if (folder.isEmpty())
            return;
        EXPECT_TRUE(window->grab().save(folder + QStringLiteral("/after-trouble.png")));
        ASSERT_TRUE(translations.select(Language::German));
        QTest::qWait(300); // the panels lay out their German texts
        EXPECT_TRUE(window->grab().save(folder + QStringLiteral("/after-trouble-de.png")));
        ASSERT_TRUE(translations.select(Language::English));
    }
    QAction* stationMenuAction(const QString& name) const {
        return window->findChild<QMenu*>(QStringLiteral("stationMenu"))->findChild<QAction*>(name);
    }
};

TEST_F(AfterTroubleOnTheDesk, AStalledStationEndsWhereTheDeskShowedItAndTheStatusBarSaysSo) {
    ASSERT_TRUE(drive(Br218, 0));
    CorrectionNotice* notice = window->correctionNotice();
    EXPECT_FALSE(notice->isVisible()) << "nothing to say before any trouble";
    QSignalSpy failed(railway(), &model::Railway::locomotiveCommandFailed);
    server.stall();
    railway()->setSpeed(Br218, 200);
    ASSERT_TRUE(QTest::qWaitFor([&] { return failed.count() >= 1; }, CommandMs));
    QTest::qWait(300);
    server.wake(); // it reads the command and its retries at once, and carries them out
    ASSERT_TRUE(QTest::qWaitFor([&] { return notice->isVisible(); }, CommandMs));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return stationSpeed(Br218) == 0 && railway()->locomotive(Br218)->speed() == 0; }, CommandMs));
    const QStringList said = notice->entries();
    ASSERT_EQ(said.size(), 1);
    EXPECT_TRUE(said.first().startsWith(QStringLiteral("BR 218"))) << said.first().toStdString();
    EXPECT_TRUE(said.first().contains(QStringLiteral("speed 20 %"))) << said.first().toStdString();
    EXPECT_TRUE(said.first().endsWith(QStringLiteral("stopped."))) << said.first().toStdString();
    EXPECT_EQ(notice->newest(), said.first());
    EXPECT_TRUE(notice->summary().contains(QStringLiteral("1 set back"))) << notice->summary().toStdString();
    EXPECT_TRUE(notice->isVisible()) << "in its row below the STOP key until read";
    ASSERT_TRUE(reported(true));
    saveScreenshots();
    notice->findChild<QPushButton*>(QStringLiteral("dismissCorrections"))->click();
    EXPECT_FALSE(notice->isVisible());
    EXPECT_TRUE(notice->entries().isEmpty());
}

TEST_F(AfterTroubleOnTheDesk, BringingTheLayoutBackInStepFromTheStationMenu) {
    ASSERT_TRUE(drive(Br218, 300));
    QAction* bringBack = stationMenuAction(QStringLiteral("bringBackInStepAction"));
    ASSERT_NE(bringBack, nullptr);
    EXPECT_TRUE(bringBack->isEnabled());
    QSignalSpy done(railway(), &model::Railway::backInStep);
    bringBack->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return done.count() == 1; }, 3 * CommandMs));
    EXPECT_EQ(stationSpeed(Br218), 300) << "its confirmed speed, sent again";
    EXPECT_TRUE(window->passingMessage()->text().startsWith(QStringLiteral("The layout is back in step")))
        << window->passingMessage()->text().toStdString();
}

TEST_F(AfterTroubleOnTheDesk, TheStopChoiceIsRememberedAndStopsEveryLocomotiveWhenBroughtBackInStep) {
    ASSERT_TRUE(drive(Br218, 300));
    ASSERT_TRUE(drive(V100, 400));
    QAction* stop = stationMenuAction(QStringLiteral("aftermathStop"));
    ASSERT_NE(stop, nullptr);
    stop->trigger();
    EXPECT_EQ(AftermathSettings::load(), model::Aftermath::StopLocomotives);
    EXPECT_EQ(railway()->aftermath(), model::Aftermath::StopLocomotives);
    QSignalSpy done(railway(), &model::Railway::backInStep);
    stationMenuAction(QStringLiteral("bringBackInStepAction"))->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return done.count() == 1; }, 3 * CommandMs));
    EXPECT_EQ(stationSpeed(Br218), 0);
    EXPECT_EQ(stationSpeed(V100), 0);
    AftermathMenu other(nullptr);
    EXPECT_EQ(other.aftermath(), model::Aftermath::StopLocomotives) << "a new window starts with the choice";
}

} // namespace
} // namespace stellwerk::ui::test
