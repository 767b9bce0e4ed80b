// Trust during a running session: while the station is silent or reconnecting, every view shows the last
// state greyed as "not reported"; after a reconnect nothing claims power on before the station says so;
// with the power off the power key and the banners on the plan and the throttles say the layout stopped.

#include "common/LayoutStateBanner.h"
#include "common/NotReported.h"
#include "common/PowerStatus.h"
#include "keyboard/TurnoutKey.h"
#include "keyboard/TurnoutPanel.h"
#include "layout/ContactTableModel.h"
#include "layout/LayoutOverview.h"
#include "stopkeys/StopGoButton.h"
#include "support/TrustTestSupport.h"
#include "throttle/ThrottlePanel.h"
#include "throttle/ThrottleWidget.h"
#include "trackplan/TrackPageView.h"
#include "trackplan/TrackPlanPanel.h"

#include <QImage>
#include <QPointer>
#include <QPushButton>
#include <QSlider>
#include <QTabWidget>
#include <QTimer>

using namespace stellwerk;
using namespace stellwerk::ui;
using Look = StopGoButton::Look;
using Shows = LayoutStateBanner::Shows;
using station::PowerState;
using SimPower = sim::SimulatedStation::Power;

namespace {

constexpr quint32 TrustedV100 = 0x18; // a locomotive of the demo layout

class StationTrustTest : public test::DeskOnTestStation {
protected:
    void SetUp() override {
        DeskOnTestStation::SetUp();
        throttle = window->throttlePanel()->addThrottle(TrustedV100);
        ASSERT_NE(throttle, nullptr);
    }
    QString powerText() const {
        return window->findChild<PowerStatus*>(QStringLiteral("powerStatus"))->text();
    }
    StopGoButton* key() const { return window->stopGoButton(); }
    LayoutStateBanner* planBanner() const { return window->trackPlan()->layoutState(); }
    LayoutStateBanner* throttleBanner() const { return window->throttlePanel()->layoutState(); }
    QString contactState(int row) const {
        const auto* contacts = window->layoutOverview()->findChild<ContactTableModel*>();
        return contacts->index(row, ContactTableModel::State).data().toString();
    }
    // Pictures of the whole window at a laptop's and a full-HD screen's size, in English and German, for
    // the documentation (only when STELLWERK_SCREENSHOT_DIR is set).
    void saveScreenshots(const QString& name) {
        const QString dir = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
        if (dir.isEmpty())
            return;
        for (const Language language : {Language::English, Language::German}) {
            ASSERT_TRUE(translations.select(language));
            for (const QSize size : {QSize(1366, 768), QSize(1920, 1080)}) {
                window->resize(size);
                QTest::qWait(150);
                const QString suffix = language == Language::German ? QStringLiteral("-de") : QString();
                EXPECT_TRUE(window->grab().save(QStringLiteral("%1/main-window-%2%3-%4x%5.png")
                                                    .arg(dir, name, suffix)
                                                    .arg(size.width())
                                                    .arg(size.height())));
            }
        }
        ASSERT_TRUE(translations.select(Language::English));
        window->resize(1366, 768);
    }

    ThrottleWidget* throttle = nullptr;
};

} // namespace

TEST_F(StationTrustTest, WhileTheStationIsSilentEveryViewSaysNotReported) {
    ASSERT_EQ(key()->look(), Look::Stop);
    ASSERT_TRUE(throttle->speedSlider()->isEnabled());
    server.stop();
    ASSERT_TRUE(reported(false));

    EXPECT_EQ(powerText(), QStringLiteral("Track power: not reported"));
    EXPECT_EQ(window->findChild<PowerStatus*>(QStringLiteral("powerStatus"))->toolTip(),
              NotReported::reason());
    EXPECT_EQ(key()->look(), Look::NotReported);
    EXPECT_EQ(key()->text(), QStringLiteral("STOP · power not reported"));
    EXPECT_TRUE(key()->isEnabled()) << "the STOP key always stays usable";
    EXPECT_TRUE(key()->stops());
    EXPECT_FALSE(throttle->speedSlider()->isEnabled());
    EXPECT_FALSE(throttle->directionButton()->isEnabled());
    EXPECT_TRUE(throttle->emergencyStopButton()->isEnabled());
    EXPECT_EQ(throttleBanner()->shows(), Shows::NotReported);
    EXPECT_TRUE(throttleBanner()->isVisible());
    EXPECT_TRUE(throttleBanner()->text().startsWith(QStringLiteral("Not reported")))
        << throttleBanner()->text().toStdString();
    EXPECT_EQ(planBanner()->shows(), Shows::NotReported);
    EXPECT_TRUE(window->trackPlan()->pageView(0)->isDimmed());
    EXPECT_TRUE(contactState(0).endsWith(QStringLiteral("(not reported)"))) << contactState(0).toStdString();
    const auto* turnout = window->turnoutPanel()->findChild<TurnoutKey*>();
    ASSERT_NE(turnout, nullptr);
    EXPECT_FALSE(turnout->isEnabled());
    saveScreenshots(QStringLiteral("not-reported"));
}

TEST_F(StationTrustTest, AfterReconnectingToAStationWhosePowerIsOffNothingSaysOn) {
    key()->click();
    ASSERT_TRUE(powerBecomes(PowerState::Stopped));
    ASSERT_EQ(server.station().power(), SimPower::Stopped);
    QStringList shown; // everything the status bar and the key said from here on
    QTimer watch;
    QObject::connect(&watch, &QTimer::timeout, [&] { shown << powerText() << key()->text(); });
    watch.start(10);

    const std::uint16_t port = server.port();
    server.stop();
    ASSERT_TRUE(reported(false));
    ASSERT_TRUE(server.start(port));
    ASSERT_TRUE(reported(true)) << "the start-up read the state again";
    watch.stop();

    EXPECT_EQ(powerText(), QStringLiteral("Track power: not reported yet"));
    EXPECT_EQ(key()->look(), Look::NotReported);
    EXPECT_EQ(planBanner()->shows(), Shows::PowerNotReported);
    EXPECT_TRUE(throttle->speedSlider()->isEnabled()) << "the locomotives' state was read again";
    EXPECT_FALSE(window->trackPlan()->pageView(0)->isDimmed());
    EXPECT_EQ(server.station().power(), SimPower::Stopped);
    for (const QString& text : shown) {
        EXPECT_FALSE(text.startsWith(QStringLiteral("Track power: on"))) << text.toStdString();
        EXPECT_NE(text, QStringLiteral("STOP")) << "STOP means: the station reports power on";
    }
}

TEST_F(StationTrustTest, WithThePowerOffTheKeyAndTheBannersSayTheLayoutStopped) {
    test::WireWatch wire(connection);
    EXPECT_FALSE(planBanner()->isVisible());
    EXPECT_FALSE(throttleBanner()->isVisible());
    key()->click();
    ASSERT_TRUE(powerBecomes(PowerState::Stopped));
    EXPECT_EQ(wire.stops(), 1);
    EXPECT_EQ(key()->look(), Look::PowerOff);
    EXPECT_EQ(key()->text(), QStringLiteral("TRACK POWER OFF · press to switch on"));
    EXPECT_FALSE(key()->stops());
    EXPECT_EQ(powerText(), QStringLiteral("Track power: off (stop)"));
    for (const LayoutStateBanner* banner : {planBanner(), throttleBanner()}) {
        EXPECT_EQ(banner->shows(), Shows::Stopped);
        EXPECT_TRUE(banner->isVisible());
        EXPECT_TRUE(banner->text().startsWith(QStringLiteral("LAYOUT STOPPED")))
            << banner->text().toStdString();
    }
    saveScreenshots(QStringLiteral("power-off"));

    key()->click();
    ASSERT_TRUE(powerBecomes(PowerState::Running));
    EXPECT_EQ(wire.goes(), 1);
    EXPECT_EQ(key()->look(), Look::Stop);
    EXPECT_FALSE(planBanner()->isVisible());
    EXPECT_FALSE(throttleBanner()->isVisible());
}

// A page view shares its page: the railway (and the layout it holds) may go first, as at the end of a
// session, and the view still draws what it showed (under AddressSanitizer this read freed memory).
TEST_F(StationTrustTest, APageViewOutlivesTheRailwayWhosePageItShows) {
    TrackPageView* view = window->trackPlan()->pageView(0);
    ASSERT_NE(view, nullptr);
    const QSize grid = view->gridSize();
    QWidget* scroll = window->trackPlan()->pageTabs()->widget(0);
    std::unique_ptr<QWidget> kept(scroll); // taken out of the panel before the railway goes
    window->trackPlan()->pageTabs()->removeTab(0);
    scroll->setParent(nullptr);
    railways.reset();
    EXPECT_EQ(window->trackPlan()->layout(), nullptr);
    EXPECT_EQ(window->trackPlan()->pageTabs()->count(), 0);
    EXPECT_EQ(view->gridSize(), grid);
    const QImage picture = view->grab().toImage();
    EXPECT_EQ(picture.size(), view->size());
}
