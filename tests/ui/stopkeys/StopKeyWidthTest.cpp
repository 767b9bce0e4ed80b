// The STOP key keeps one width whatever it shows (STOP, TRACK POWER OFF, power not reported), in English
// and German, so that Connect… beside it never moves when the power changes.

#include "stopkeys/StopGoButton.h"
#include "support/TrustTestSupport.h"

#include <QToolBar>
#include <QToolButton>

using namespace stellwerk;
using namespace stellwerk::ui;
using Look = StopGoButton::Look;

namespace {

class StopKeyWidthTest : public test::DeskOnTestStation, public ::testing::WithParamInterface<Language> {
protected:
    Language deskLanguage() const override { return GetParam(); }

    StopGoButton* key() const { return window->stopGoButton(); }
    // Where Connect… stands in the toolbar.
    int connectLeft() const {
        const auto* bar = qobject_cast<QToolBar*>(key()->parentWidget());
        const auto* connect = window->findChild<QAction*>(QStringLiteral("connectAction"));
        const QWidget* button =
            bar && connect ? bar->widgetForAction(const_cast<QAction*>(connect)) : nullptr;
        return button ? button->x() : -1;
    }
    // The key's width and Connect…'s place once the key shows `look`.
    std::pair<int, int> measured(Look look) const {
        EXPECT_TRUE(QTest::qWaitFor([&] { return key()->look() == look; }, 3 * CommandMs));
        QTest::qWait(30); // the toolbar lays itself out again
        return {key()->width(), connectLeft()};
    }
};

} // namespace

TEST_P(StopKeyWidthTest, TheKeyKeepsItsWidthInEveryLook) {
    const auto stop = measured(Look::Stop);
    railway()->stop();
    const auto powerOff = measured(Look::PowerOff);
    EXPECT_GT(key()->fontMetrics().horizontalAdvance(key()->text()),
              key()->fontMetrics().horizontalAdvance(QStringLiteral("STOP")))
        << "the longer text is shown";
    server.stop();
    const auto notReported = measured(Look::NotReported);
    EXPECT_EQ(stop.first, powerOff.first) << "STOP and TRACK POWER OFF";
    EXPECT_EQ(stop.first, notReported.first) << "STOP and power not reported";
    EXPECT_EQ(stop.second, powerOff.second) << "Connect… moved";
    EXPECT_EQ(stop.second, notReported.second) << "Connect… moved";
    EXPECT_GE(key()->width(), key()->minimumSizeHint().width()) << "and the text is not cut";
}

INSTANTIATE_TEST_SUITE_P(, StopKeyWidthTest, ::testing::Values(Language::English, Language::German),
                         [](const ::testing::TestParamInfo<Language>& info) {
                             return info.param == Language::German ? "German" : "English";
                         });
