// The throttles against the demo layout's simulated CS2 on a loopback port: what a throttle sends, the
// station carries out (seen through a second connection, as another controller would see it); what
// another controller does shows in the throttle; what the station does not acknowledge is marked.

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "common/Contrast.h"
#include "common/FunctionIcons.h"
#include "common/LocomotivePictureBook.h"
#include "model/Railway.h"
#include "shell/Translations.h"
#include "stopkeys/StopGoButton.h"
#include "support/StationTestSupport.h"
#include "throttle/FunctionPad.h"
#include "throttle/SpeedScale.h"
#include "throttle/ThrottlePanel.h"
#include "throttle/ThrottleWidget.h"

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QMessageBox>
#include <QPalette>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QShortcut>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <algorithm>
#include <functional>
#include <gtest/gtest.h>
#include <map>

using namespace stellwerk;
using namespace stellwerk::ui;
using namespace std::chrono_literals;
using State = connection::StationConnection::State;
using Control = model::Railway::LocomotiveControl;

namespace {

constexpr int ThrottleCommandMs = 5000;
constexpr quint32 DrivenV100 = 0x18; // V 100 2023, MM2 24, tachomax 100: stands still in the demo
constexpr quint32 Br218 = 0x4001;    // BR 218 Ost, mfx, tachomax 140
constexpr int Horn = 2;              // V 100's F2: icon 138, the horn, momentary
constexpr int SendIntervalMs = 60;   // longer than a throttle waits before it sends a dragged speed

connection::ConnectionSettings impatient() {
    connection::ConnectionSettings settings;
    settings.session.commands.timeout = 150ms;
    settings.session.commands.retries = 0;
    settings.session.liveness.interval = 400ms; // silent after 1.2 s without an answer
    return settings;
}

// The simulated station stops answering anyone while the connections stay open: a stalled station.
void deafen(test::TestStation& station) {
    QObject::disconnect(&station.station(), &sim::SimulatedStation::framesEmitted, nullptr, nullptr);
}

// Answers the next modal window (the question a throttle asks) with `answer`, and notes its text.
class QuestionAnswer : public QObject {
public:
    explicit QuestionAnswer(std::function<void(QMessageBox*)> answer) : m_answer(std::move(answer)) {
        connect(&m_poll, &QTimer::timeout, this, [this] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box || m_answered)
                return;
            m_answered = true;
            asked = box->text() + QLatin1Char('\n') + box->informativeText();
            m_answer(box);
        });
        m_poll.start(10);
    }
    QString asked;

private:
    std::function<void(QMessageBox*)> m_answer;
    QTimer m_poll;
    bool m_answered = false;
};

// The colour most pixels of `image` have (a button's fill).
QColor mostFrequentColour(const QImage& image) {
    std::map<QRgb, int> counts;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            ++counts[image.pixel(x, y)];
    return QColor(std::max_element(counts.begin(), counts.end(), [](const auto& a, const auto& b) {
                      return a.second < b.second;
                  })->first);
}

int colourDistance(const QColor& a, const QColor& b) {
    return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
}

QPushButton* buttonNamed(QMessageBox* box, const QString& text) {
    for (QAbstractButton* button : box->buttons())
        if (button->text() == text)
            return qobject_cast<QPushButton*>(button);
    return nullptr;
}

// A throttle on one connection to a TestStation, and a second connection ("another controller").
class ThrottleTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        ASSERT_TRUE(testStation.start());
        QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, &throttle,
                         &ThrottleWidget::setRailway);
        connection.connectTo(testStation.url());
        other.connectTo(testStation.url());
        ASSERT_TRUE(test::waitForState(connection, State::Ready));
        ASSERT_TRUE(test::waitForState(other, State::Ready));
        ASSERT_NE(railways.railway(), nullptr);
        throttle.setLocomotive(DrivenV100);
        throttle.show();
    }

    const model::Locomotive& mine() const { return *railways.railway()->locomotive(DrivenV100); }
    const model::Locomotive& seenByOther() const { return *otherRailways.railway()->locomotive(DrivenV100); }
    QToolButton* key(int function) const { return throttle.functions()->button(function); }
    static bool waitFor(const std::function<bool()>& condition) {
        return QTest::qWaitFor(condition, ThrottleCommandMs);
    }

    Translations translations;
    test::TestStation testStation;
    connection::StationConnection connection{support::withEmbeddedStation(impatient())};
    connection::StationConnection other{support::withEmbeddedStation()};
    binding::RailwayBinding railways{connection};
    binding::RailwayBinding otherRailways{other};
    ThrottleWidget throttle;
};

} // namespace

TEST_F(ThrottleTest, PicksALocomotiveFromTheStationsListWithItsAddressAndScale) {
    QComboBox* choice = throttle.locomotiveChoice();
    ASSERT_EQ(choice->count(), 13) << "a prompt and the demo's 12 locomotives";
    EXPECT_EQ(choice->currentText(), QStringLiteral("V 100 2023 (MM2 24)"));
    const int br218 = choice->findData(Br218);
    ASSERT_GE(br218, 0);
    EXPECT_EQ(choice->itemText(br218), QStringLiteral("BR 218 Ost (MFX 1)"));
    EXPECT_EQ(throttle.speedScale()->tachoMax(), 100);
    EXPECT_EQ(throttle.speedScale()->markTexts().last(), QStringLiteral("100 km/h"));
    EXPECT_EQ(throttle.speedText(), QStringLiteral("0 km/h"));

    QSignalSpy chosen(&throttle, &ThrottleWidget::locomotiveChosen);
    choice->setCurrentIndex(br218);
    emit choice->activated(br218);
    EXPECT_EQ(throttle.locomotive(), Br218);
    ASSERT_EQ(chosen.count(), 1);
    EXPECT_EQ(throttle.speedScale()->tachoMax(), 140);
}

TEST_F(ThrottleTest, FunctionKeysShowTheirIconAndHowTheyAct) {
    ASSERT_NE(key(0), nullptr);
    EXPECT_FALSE(key(0)->icon().isNull()) << "F0 is the light (icon 1)";
    EXPECT_TRUE(key(0)->toolTip().startsWith(QStringLiteral("F0: Light (on/off)")))
        << key(0)->toolTip().toStdString();
    ASSERT_NE(key(Horn), nullptr);
    EXPECT_TRUE(key(Horn)->toolTip().startsWith(QStringLiteral("F2: Horn (on while held)")));
    EXPECT_EQ(key(9), nullptr) << "F9 has no icon in the file: no key";
}

TEST_F(ThrottleTest, TheSliderDrivesTheLocomotiveAndTheStationConfirmsIt) {
    throttle.speedSlider()->setValue(50);
    ASSERT_TRUE(waitFor([&] { return seenByOther().speed() == 500; }));
    ASSERT_TRUE(waitFor([&] { return mine().speed() == 500; }));
    EXPECT_EQ(throttle.speedSlider()->value(), 50);
    EXPECT_EQ(throttle.speedText(), QStringLiteral("50 km/h"));
    EXPECT_FALSE(throttle.isUnacknowledged(Control::Speed));
}

TEST_F(ThrottleTest, AFunctionKeyTogglesTheFunctionOnTheStation) {
    const bool before = mine().functionOn(0); // the demo's V 100 may start with its light on
    EXPECT_EQ(key(0)->isChecked(), before);
    QTest::mouseClick(key(0), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return seenByOther().functionOn(0) != before; }));
    ASSERT_TRUE(waitFor([&] { return key(0)->isChecked() != before; }));
    QTest::mouseClick(key(0), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return seenByOther().functionOn(0) == before; }));
    ASSERT_TRUE(waitFor([&] { return key(0)->isChecked() == before; }));
}

TEST_F(ThrottleTest, AMomentaryFunctionIsOnOnlyWhileItsKeyIsHeld) {
    QTest::mousePress(key(Horn), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return seenByOther().functionOn(Horn); }));
    ASSERT_TRUE(waitFor([&] { return key(Horn)->isChecked(); }));
    QTest::mouseRelease(key(Horn), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return !seenByOther().functionOn(Horn); }));
    ASSERT_TRUE(waitFor([&] { return !key(Horn)->isChecked(); }));
}

TEST_F(ThrottleTest, ATimedFunctionSwitchesOffAgainByItself) {
    constexpr quint32 Ice3 = 0x4002;
    constexpr int TimedHorn = 3; // ICE 3's F3: the horn for 2 (..dauer=2)
    throttle.setLocomotive(Ice3);
    ASSERT_NE(key(TimedHorn), nullptr);
    EXPECT_TRUE(key(TimedHorn)->toolTip().startsWith(QStringLiteral("F3: Horn (on for 2 s)")));
    const model::Locomotive& ice3 = *otherRailways.railway()->locomotive(Ice3);
    QTest::mouseClick(key(TimedHorn), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return ice3.functionOn(TimedHorn); }));
    ASSERT_TRUE(waitFor([&] { return !ice3.functionOn(TimedHorn); }));
    ASSERT_TRUE(waitFor([&] { return !key(TimedHorn)->isChecked(); }));
}

TEST_F(ThrottleTest, StopLocoStopsOnlyThisLocomotive) {
    throttle.speedSlider()->setValue(60);
    ASSERT_TRUE(waitFor([&] { return mine().speed() == 600; }));
    otherRailways.railway()->setSpeed(Br218, 400);
    ASSERT_TRUE(waitFor([&] { return railways.railway()->locomotive(Br218)->speed() == 400; }));
    QTest::mouseClick(throttle.emergencyStopButton(), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return mine().speed() == 0 && throttle.speedSlider()->value() == 0; }));
    EXPECT_EQ(throttle.speedText(), QStringLiteral("0 km/h"));
    EXPECT_EQ(railways.railway()->locomotive(Br218)->speed(), 400);
    EXPECT_EQ(otherRailways.railway()->locomotive(Br218)->speed(), 400);
}

TEST_F(ThrottleTest, WhatAnotherControllerDoesShowsInTheThrottle) {
    otherRailways.railway()->setSpeed(DrivenV100, 300);
    ASSERT_TRUE(waitFor([&] { return throttle.speedSlider()->value() == 30; }));
    EXPECT_EQ(throttle.speedText(), QStringLiteral("30 km/h"));
    otherRailways.railway()->setFunction(DrivenV100, 0, true);
    ASSERT_TRUE(waitFor([&] { return key(0)->isChecked(); }));
    otherRailways.railway()->setDirection(DrivenV100, cs2::Direction::Backward);
    ASSERT_TRUE(waitFor([&] { return throttle.directionButton()->text() == QStringLiteral("◀ Backward"); }));
}

TEST_F(ThrottleTest, ACommandTheStationDoesNotAcknowledgeIsMarked) {
    testStation.stop();
    throttle.speedSlider()->setValue(40);
    ASSERT_TRUE(waitFor([&] { return throttle.isUnacknowledged(Control::Speed); }));
    EXPECT_TRUE(throttle.speedSlider()->toolTip().startsWith(
        QStringLiteral("The station did not acknowledge the last command")))
        << throttle.speedSlider()->toolTip().toStdString();
    EXPECT_EQ(throttle.speedSlider()->value(), 0) << "back to what the station confirmed";
    const bool light = mine().functionOn(0);
    // With the station gone its state is not reported: the keys are greyed, so the command comes from
    // the railway itself (another panel, a route), and the throttle still marks it.
    ASSERT_TRUE(waitFor([&] { return !railways.railway()->isStateReported(); }));
    EXPECT_FALSE(key(0)->isEnabled());
    railways.railway()->toggleFunction(DrivenV100, 0);
    ASSERT_TRUE(waitFor([&] { return throttle.isUnacknowledged(Control::Function, 0); }));
    EXPECT_TRUE(key(0)->property("unacknowledged").toBool());
    EXPECT_EQ(key(0)->isChecked(), light) << "the key still shows what the station confirmed";
    EXPECT_TRUE(key(0)->toolTip().contains(QStringLiteral("did not acknowledge")));
    if (const QString dir = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR"); !dir.isEmpty()) {
        EXPECT_TRUE(throttle.grab().save(dir + QStringLiteral("/throttle-unacknowledged.png")));
    }
}

// Issue 32: with the station not answering, Up showed "5 km/h" as if confirmed and then fell back to 0
// without the outline. The big number shows only what the station confirmed; the slider's request is shown
// as a request, and a request that failed stays outlined with the reason until the user moves the slider.
TEST_F(ThrottleTest, TheBigNumberShowsOnlyWhatTheStationConfirmed) {
    throttle.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&throttle));
    throttle.setFocus();
    deafen(testStation);
    QStringList shown; // every big number the throttle showed from here on
    QTimer watch;
    QObject::connect(&watch, &QTimer::timeout, [&] { shown << throttle.speedText(); });
    watch.start(1);

    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Up);
    EXPECT_EQ(throttle.speedSlider()->value(), 5) << "the slider leads";
    EXPECT_EQ(throttle.speedText(), QStringLiteral("0 km/h")) << "nothing was confirmed";
    EXPECT_EQ(throttle.requestText(), QStringLiteral("Requested: 5 km/h"));
    EXPECT_TRUE(throttle.speedArea()->property("requested").toBool());
    ASSERT_TRUE(waitFor([&] { return throttle.isUnacknowledged(Control::Speed); }));
    EXPECT_EQ(throttle.speedSlider()->value(), 0) << "back to what the station confirmed";
    EXPECT_EQ(throttle.requestText(), QString());
    EXPECT_FALSE(throttle.speedArea()->property("requested").toBool());
    EXPECT_TRUE(throttle.speedArea()->property("unacknowledged").toBool());
    EXPECT_TRUE(throttle.speedArea()->toolTip().startsWith(
        QStringLiteral("The station did not acknowledge the last command: no answer")))
        << throttle.speedArea()->toolTip().toStdString();

    // The station falls silent: the throttle greys, and the failed request stays outlined.
    ASSERT_TRUE(waitFor([&] { return !railways.railway()->isStateReported(); }));
    EXPECT_TRUE(throttle.isUnacknowledged(Control::Speed));
    EXPECT_TRUE(throttle.speedArea()->property("unacknowledged").toBool());
    EXPECT_TRUE(throttle.speedSlider()->toolTip().contains(QStringLiteral("did not acknowledge")));
    watch.stop();
    shown.removeDuplicates();
    EXPECT_EQ(shown, QStringList{QStringLiteral("0 km/h")});
}

TEST_F(ThrottleTest, AFailedSpeedStaysOutlinedUntilTheUserMovesTheSliderAgain) {
    deafen(testStation);
    throttle.speedSlider()->setValue(40);
    ASSERT_TRUE(waitFor([&] { return throttle.isUnacknowledged(Control::Speed); }));
    emit railways.railway()->locomotivesChanged({DrivenV100}); // the model shows the confirmed state again
    emit railways.railway()->loaded();
    EXPECT_TRUE(throttle.isUnacknowledged(Control::Speed)) << "not cleared by the model";
    throttle.speedSlider()->setValue(20);
    EXPECT_FALSE(throttle.isUnacknowledged(Control::Speed)) << "the user asked anew";
    EXPECT_FALSE(throttle.speedArea()->property("unacknowledged").toBool());
    EXPECT_EQ(throttle.requestText(), QStringLiteral("Requested: 20 km/h"));
}

TEST_F(ThrottleTest, AFailedDirectionAndFunctionStayOutlinedWhileTheStationIsSilent) {
    deafen(testStation);
    throttle.directionButton()->click();
    QTest::mouseClick(key(0), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] {
        return throttle.isUnacknowledged(Control::Direction) &&
               throttle.isUnacknowledged(Control::Function, 0);
    }));
    QPushButton* direction = throttle.directionButton();
    EXPECT_TRUE(waitFor([&] { return direction->height() >= direction->sizeHint().height(); }))
        << "the outline's border and padding get their room; the text is not cut: " << direction->height()
        << " < " << direction->sizeHint().height();
    ASSERT_TRUE(waitFor([&] { return !railways.railway()->isStateReported(); }));
    EXPECT_TRUE(throttle.isUnacknowledged(Control::Direction));
    EXPECT_TRUE(throttle.directionButton()->property("unacknowledged").toBool());
    EXPECT_TRUE(throttle.isUnacknowledged(Control::Function, 0));
    ASSERT_NE(key(0), nullptr);
    EXPECT_TRUE(key(0)->property("unacknowledged").toBool()) << "the key made anew keeps its outline";
    EXPECT_TRUE(key(0)->toolTip().contains(QStringLiteral("did not acknowledge")));
}

TEST_F(ThrottleTest, GreyedControlsIgnoreTheirKeysButStopLocoStillStops) {
    testStation.stop();
    ASSERT_TRUE(waitFor([&] { return !railways.railway()->isStateReported(); }));
    QSignalSpy sent(railways.railway(), &model::Railway::locomotiveCommandSent);
    QWidget* focus = &throttle; // the greyed slider gave the focus away
    for (const Qt::Key pressed : {Qt::Key_Up, Qt::Key_PageUp, Qt::Key_R, Qt::Key_0})
        QTest::keyClick(focus, pressed);
    QTest::qWait(SendIntervalMs);
    EXPECT_EQ(throttle.speedSlider()->value(), 0);
    EXPECT_EQ(sent.count(), 0) << "greyed: the keys of speed, direction and functions do nothing";
    QTest::keyClick(focus, Qt::Key_E);
    ASSERT_EQ(sent.count(), 1);
    EXPECT_EQ(sent.first().at(1).value<Control>(), Control::EmergencyStop);
}

TEST_F(ThrottleTest, AnAcknowledgedCommandClearsTheMark) {
    // The railway reports a failure and later an acknowledgement for the same control, as it does when
    // the station misses one command and answers the next.
    model::Railway* railway = railways.railway();
    emit railway->locomotiveCommandFailed(DrivenV100, Control::Speed, -1, QStringLiteral("no answer"));
    ASSERT_TRUE(throttle.isUnacknowledged(Control::Speed));
    throttle.speedSlider()->setValue(20);
    ASSERT_TRUE(waitFor([&] { return mine().speed() == 200; }));
    ASSERT_TRUE(waitFor([&] { return !throttle.isUnacknowledged(Control::Speed); }));
    EXPECT_FALSE(throttle.speedSlider()->toolTip().contains(QStringLiteral("did not acknowledge")));
}

TEST_F(ThrottleTest, KeysDriveSpeedDirectionAndFunctions) {
    throttle.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&throttle));
    throttle.setFocus();
    QWidget* focus = QApplication::focusWidget();
    ASSERT_NE(focus, nullptr);
    QTest::keyClick(focus, Qt::Key_Up);
    QTest::keyClick(focus, Qt::Key_Plus);
    ASSERT_TRUE(waitFor([&] { return seenByOther().speed() == 100; })) << "two steps of 5 %";
    QTest::keyClick(focus, Qt::Key_Minus);
    ASSERT_TRUE(waitFor([&] { return seenByOther().speed() == 50; }));
    const bool light = seenByOther().functionOn(0);
    QTest::keyClick(focus, Qt::Key_0);
    ASSERT_TRUE(waitFor([&] { return seenByOther().functionOn(0) != light; }));
    QTest::keyPress(focus, Qt::Key_2);
    ASSERT_TRUE(waitFor([&] { return seenByOther().functionOn(Horn); }));
    QTest::keyRelease(focus, Qt::Key_2);
    ASSERT_TRUE(waitFor([&] { return !seenByOther().functionOn(Horn); }));
    QTest::keyClick(focus, Qt::Key_R);
    ASSERT_TRUE(waitFor([&] { return seenByOther().direction() == cs2::Direction::Backward; }));
    QTest::keyClick(focus, Qt::Key_PageUp);
    ASSERT_TRUE(waitFor([&] { return seenByOther().speed() == 250; })) << "a page is 25 %";
    QTest::keyClick(focus, Qt::Key_E);
    ASSERT_TRUE(waitFor([&] { return mine().speed() == 0 && throttle.speedSlider()->value() == 0; }));
}

namespace {

// Picks `loco` in the throttle's list as a user does.
void pick(ThrottleWidget& throttle, quint32 loco) {
    QComboBox* choice = throttle.locomotiveChoice();
    const int index = choice->findData(loco);
    ASSERT_GE(index, 0);
    choice->setCurrentIndex(index);
    emit choice->activated(index);
}

} // namespace

TEST_F(ThrottleTest, ChangingTheLocomotiveWhileItRunsAsksFirstAndEscapeKeepsIt) {
    throttle.speedSlider()->setValue(30);
    ASSERT_TRUE(waitFor([&] { return mine().speed() == 300; }));
    QuestionAnswer escape([](QMessageBox* box) { QTest::keyClick(box, Qt::Key_Escape); });
    pick(throttle, Br218);
    EXPECT_EQ(throttle.locomotive(), DrivenV100) << "Escape keeps the old locomotive";
    EXPECT_EQ(throttle.locomotiveChoice()->currentText(), QStringLiteral("V 100 2023 (MM2 24)"));
    EXPECT_TRUE(escape.asked.startsWith(
        QStringLiteral("V 100 2023 is running (30 km/h). Drive BR 218 Ost with this throttle instead?")))
        << escape.asked.toStdString();

    QuestionAnswer no([](QMessageBox* box) { buttonNamed(box, QStringLiteral("Keep V 100 2023"))->click(); });
    pick(throttle, Br218);
    EXPECT_EQ(throttle.locomotive(), DrivenV100);
    EXPECT_FALSE(no.asked.isEmpty());

    QuestionAnswer yes(
        [](QMessageBox* box) { buttonNamed(box, QStringLiteral("Drive BR 218 Ost"))->click(); });
    pick(throttle, Br218);
    EXPECT_EQ(throttle.locomotive(), Br218);
    EXPECT_EQ(mine().speed(), 300) << "the V 100 runs on, as the question said";
}

TEST_F(ThrottleTest, ChangingAStandingLocomotiveAsksNothing) {
    ASSERT_EQ(mine().speed(), 0);
    QuestionAnswer never([](QMessageBox* box) { box->reject(); });
    pick(throttle, Br218);
    EXPECT_EQ(throttle.locomotive(), Br218);
    EXPECT_TRUE(never.asked.isEmpty());
}

// The per-loco stop must not look like the toolbar's STOP for the whole layout, yet read as a stop.
TEST_F(ThrottleTest, StopLocoIsNotTheRedOfTheLayoutsStop) {
    railways.railway()->go();
    StopGoButton layoutStop;
    layoutStop.setRailway(railways.railway());
    ASSERT_TRUE(waitFor([&] { return layoutStop.look() == StopGoButton::Look::Stop; }));
    layoutStop.resize(layoutStop.sizeHint());
    layoutStop.show();
    throttle.resize(throttle.sizeHint());
    QTest::qWait(20);
    const QImage stop = layoutStop.grab().toImage();
    const QImage loco = throttle.emergencyStopButton()->grab().toImage();
    const QColor stopFill = mostFrequentColour(stop);
    const QColor locoFill = mostFrequentColour(loco);
    EXPECT_EQ(stopFill, QColor(0xc6, 0x28, 0x28)) << stopFill.name().toStdString();
    EXPECT_GT(colourDistance(stopFill, locoFill), 150)
        << stopFill.name().toStdString() << " " << locoFill.name().toStdString();
    const QColor outline = loco.pixelColor(1, loco.height() / 2);
    EXPECT_GT(outline.red(), outline.green() + 60) << "red outline: " << outline.name().toStdString();
    EXPECT_GE(Contrast::ratio(outline, locoFill), Contrast::ForText);
    if (const QString dir = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR"); !dir.isEmpty()) {
        EXPECT_TRUE(throttle.grab().save(dir + QStringLiteral("/throttle-stop-loco.png")));
    }
}

TEST_F(ThrottleTest, SpaceAndEscapeStayWithTheWindow) {
    QWidget window;
    auto* inside = new ThrottleWidget(&window);
    inside->setRailway(railways.railway());
    inside->setLocomotive(DrivenV100);
    QShortcut stop(QKeySequence(Qt::Key_Space), &window);
    QShortcut escape(QKeySequence(Qt::Key_Escape), &window);
    QSignalSpy stops(&stop, &QShortcut::activated);
    QSignalSpy escapes(&escape, &QShortcut::activated);
    window.show();
    window.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
    inside->setFocus();
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape);
    EXPECT_EQ(stops.count(), 1);
    EXPECT_EQ(escapes.count(), 1);
}

class ThrottlePanelTest : public ThrottleTest {
protected:
    void SetUp() override {
        QSettings("Stellwerk", "Stellwerk").remove("throttles");
        ThrottleTest::SetUp();
    }
};

TEST_F(ThrottlePanelTest, RemembersWhichLocomotivesWereOpen) {
    {
        ThrottlePanel panel;
        EXPECT_TRUE(panel.throttles().isEmpty());
        panel.setRailway(railways.railway());
        panel.addThrottle(Br218);
        panel.addThrottle(DrivenV100);
        ThrottleWidget* third = panel.addThrottle();
        panel.removeThrottle(panel.throttles().first());
        third->setLocomotive(Br218);
    }
    ThrottlePanel restored;
    ASSERT_EQ(restored.throttles().size(), 2);
    EXPECT_EQ(restored.throttles()[0]->locomotive(), DrivenV100);
    EXPECT_EQ(restored.throttles()[1]->locomotive(), Br218);
    QComboBox* first = restored.throttles()[0]->locomotiveChoice();
    EXPECT_EQ(first->currentText(), QStringLiteral("Locomotive 0x18 (waiting for the station)"));
    restored.setRailway(railways.railway());
    EXPECT_EQ(first->currentText(), QStringLiteral("V 100 2023 (MM2 24)"));
}

TEST_F(ThrottlePanelTest, SaysWhatToDoWhileThereIsNothingToDrive) {
    ThrottlePanel panel;
    EXPECT_TRUE(panel.emptyText().startsWith(QStringLiteral("No station connected")))
        << panel.emptyText().toStdString();
    panel.setRailway(railways.railway());
    EXPECT_TRUE(
        panel.emptyText().startsWith(QStringLiteral("No throttle open. Open one for a locomotive below")))
        << panel.emptyText().toStdString();
    ThrottleWidget* throttle = panel.addThrottle();
    EXPECT_EQ(panel.emptyText(), QString());
    EXPECT_EQ(throttle->locomotiveChoice()->currentText(), QStringLiteral("Choose a locomotive…"));
    EXPECT_FALSE(throttle->speedSlider()->isEnabled()) << "nothing to drive yet";
    panel.removeThrottle(throttle);
    EXPECT_TRUE(panel.emptyText().startsWith(QStringLiteral("No throttle open")));
}

TEST_F(ThrottlePanelTest, ANewcomerIsOfferedTheRunningLocomotivesToDrive) {
    ThrottlePanel panel;
    EXPECT_TRUE(panel.driveOffers().isEmpty()) << "nothing to offer without a station";
    panel.setRailway(railways.railway());
    panel.show();
    ASSERT_EQ(panel.driveOffers().size(), ThrottlePanel::MaximumOffers);
    // A running locomotive comes first (the list starts with BR 218, which stands here).
    railways.railway()->setSpeed(DrivenV100, 300);
    ASSERT_TRUE(waitFor([&] {
        return panel.driveOffers()[0]->text() == QStringLiteral("Drive V 100 2023 (running)");
    })) << panel.driveOffers()[0]->text().toStdString();
    for (qsizetype i = 1; i < panel.driveOffers().size(); ++i)
        EXPECT_FALSE(panel.driveOffers()[i]->text().endsWith(QStringLiteral("(running)")))
            << panel.driveOffers()[i]->text().toStdString();
    EXPECT_TRUE(panel.driveOffers()[0]->isVisible());

    panel.driveOffers()[0]->click();
    ASSERT_EQ(panel.throttles().size(), 1);
    EXPECT_EQ(panel.throttles().first()->locomotive(), DrivenV100);
    EXPECT_TRUE(panel.driveOffers().isEmpty()) << "a throttle is open: no more offers";
    panel.removeThrottle(panel.throttles().first());
    EXPECT_EQ(panel.driveOffers().size(), ThrottlePanel::MaximumOffers) << "offered again";
}

// The offers follow a language switch at once, as the window's other texts do.
TEST_F(ThrottlePanelTest, TheOffersSpeakTheLanguageChosenWhileTheyShow) {
    ThrottlePanel panel;
    panel.setRailway(railways.railway());
    panel.show();
    railways.railway()->setSpeed(DrivenV100, 300);
    ASSERT_TRUE(waitFor(
        [&] { return panel.driveOffers()[0]->text() == QStringLiteral("Drive V 100 2023 (running)"); }));
    ASSERT_TRUE(translations.select(Language::German));
    EXPECT_TRUE(waitFor([&] {
        return panel.driveOffers()[0]->text() == QStringLiteral("V 100 2023 fahren (fährt)");
    })) << panel.driveOffers()[0]->text().toStdString();
    EXPECT_EQ(panel.driveOffers()[1]->text(), QStringLiteral("BR 218 Ost fahren"));
    ASSERT_TRUE(translations.select(Language::English));
}

// Issue 32: "Add throttle" in a panel one throttle wide showed the previous throttle, not the new one.
TEST_F(ThrottlePanelTest, AddThrottleScrollsTheNewThrottleIntoView) {
    ThrottlePanel panel;
    panel.setRailway(railways.railway());
    panel.addThrottle(Br218);
    const QSize one = panel.throttles().first()->sizeHint();
    panel.resize(one.width() + 40, one.height() + 120); // room for one throttle, not two
    panel.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
    auto* scroll = panel.findChild<QScrollArea*>();
    ASSERT_NE(scroll, nullptr);
    auto* add = panel.findChild<QPushButton*>(QStringLiteral("addThrottle"));
    ASSERT_NE(add, nullptr);
    const auto inView = [&](const ThrottleWidget* throttle) {
        const QRect shown(throttle->mapTo(scroll->viewport(), QPoint(0, 0)), throttle->size());
        return scroll->viewport()->rect().contains(shown);
    };
    for (int added = 2; added <= 4; ++added) {
        add->click();
        ASSERT_EQ(panel.throttles().size(), added);
        ThrottleWidget* fresh = panel.throttles().last();
        const ThrottleWidget* before = panel.throttles()[added - 2];
        EXPECT_TRUE(waitFor([&] { return fresh->isVisible() && fresh->y() > before->y() && inView(fresh); }))
            << "throttle " << added << " at " << fresh->mapTo(scroll->viewport(), QPoint(0, 0)).y()
            << ", viewport " << scroll->viewport()->height() << " high";
        EXPECT_FALSE(inView(before)) << "one throttle fits";
    }
}

TEST_F(ThrottlePanelTest, AltAndANumberPutTheKeyboardOnThatThrottle) {
    ThrottlePanel panel;
    panel.setRailway(railways.railway());
    panel.addThrottle(Br218);
    panel.addThrottle(DrivenV100);
    panel.show();
    panel.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&panel));
    QTest::keyClick(&panel, Qt::Key_2, Qt::AltModifier);
    EXPECT_TRUE(panel.throttles()[1]->isAncestorOf(QApplication::focusWidget()));
    QTest::keyClick(&panel, Qt::Key_1, Qt::AltModifier);
    EXPECT_TRUE(panel.throttles()[0]->isAncestorOf(QApplication::focusWidget()));
    EXPECT_FALSE(panel.focusThrottle(3));
}

namespace {

QPalette darkPalette() {
    QPalette dark;
    dark.setColor(QPalette::Window, QColor(0x2b, 0x2b, 0x2b));
    dark.setColor(QPalette::WindowText, QColor(0xe6, 0xe6, 0xe6));
    dark.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
    dark.setColor(QPalette::Text, QColor(0xe6, 0xe6, 0xe6));
    dark.setColor(QPalette::Button, QColor(0x3c, 0x3c, 0x3c));
    dark.setColor(QPalette::ButtonText, QColor(0xe6, 0xe6, 0xe6));
    dark.setColor(QPalette::Mid, QColor(0x5a, 0x5a, 0x5a));
    dark.setColor(QPalette::Highlight, QColor(0x2f, 0x7d, 0xd1));
    dark.setColor(QPalette::HighlightedText, Qt::white);
    dark.setColor(QPalette::Disabled, QPalette::WindowText, QColor(0x9a, 0x9a, 0x9a));
    dark.setColor(QPalette::Disabled, QPalette::ButtonText, QColor(0x80, 0x80, 0x80));
    return dark;
}

} // namespace

// The colours of greyed keys keep 4.5:1 for their text and drawings, in light and dark palettes, and a
// greyed key that is on stands out less than a usable one.
TEST(FunctionPadColours, GreyedKeysKeepTheirContrastInLightAndDarkPalettes) {
    for (const QPalette& palette : {QApplication::palette(), darkPalette()}) {
        const FunctionPad::Greyed greyed = FunctionPad::greyed(palette);
        const QColor button = palette.color(QPalette::Active, QPalette::Button);
        const QColor text = palette.color(QPalette::Active, QPalette::ButtonText);
        const QColor highlight = palette.color(QPalette::Active, QPalette::Highlight);
        EXPECT_GE(Contrast::ratio(greyed.offText, greyed.offBackground), Contrast::ForText);
        EXPECT_GE(Contrast::ratio(greyed.onText, greyed.onBackground), Contrast::ForText);
        EXPECT_LT(Contrast::ratio(greyed.offText, greyed.offBackground), Contrast::ratio(text, button))
            << "greyed text is paler than usable text";
        EXPECT_LT(Contrast::ratio(greyed.onBackground, button), Contrast::ratio(highlight, button));
        EXPECT_NE(greyed.onBackground, greyed.offBackground) << "on and off stay apart";
    }
}

TEST(ContrastRatio, FollowsTheGuidelinesFormula) {
    EXPECT_NEAR(Contrast::ratio(Qt::black, Qt::white), 21.0, 0.01);
    EXPECT_NEAR(Contrast::ratio(Qt::white, Qt::white), 1.0, 0.001);
    EXPECT_NEAR(Contrast::ratio(QColor(0x76, 0x76, 0x76), Qt::white), 4.54, 0.02);
    const QColor grey = Contrast::faded(Qt::black, Qt::white, Contrast::ForText);
    EXPECT_GE(Contrast::ratio(grey, Qt::white), Contrast::ForText);
    EXPECT_GT(grey.lightness(), 0) << "faded";
    const double kept = Contrast::keptFor(Qt::black, Qt::white, Contrast::ForDrawings);
    EXPECT_GE(kept, 0.5);
    EXPECT_LT(kept, 1.0);
    EXPECT_GE(Contrast::ratio(Contrast::mix(Qt::black, Qt::white, kept), Qt::white), Contrast::ForDrawings);
}

// Three throttles side by side, each wide enough for its keys and texts. With STELLWERK_SCREENSHOT_DIR
// set, the page is saved as throttles.png (and throttles-dark.png) there for docs/screenshots.
TEST_F(ThrottlePanelTest, ThreeThrottlesStandSideBySideUnclipped) {
    // The station here has no web server: the pictures come from an icons folder, as from an opened layout.
    connection::LocomotivePictures pictures;
    pictures.setFolder(QStringLiteral(STELLWERK_DEMO_ICONS_DIR));
    LocomotivePictureBook book(&pictures);
    ThrottlePanel panel;
    panel.setPictures(&book);
    panel.setRailway(railways.railway());
    constexpr quint32 Ice3 = 0x4002;
    for (const quint32 loco : {Br218, Ice3, DrivenV100})
        panel.addThrottle(loco);
    model::Railway* railway = railways.railway();
    railway->setSpeed(Br218, 640);
    railway->setFunction(Br218, 0, true);
    railway->setFunction(Br218, 1, true);
    railway->setFunction(DrivenV100, 0, true);
    railway->setDirection(Ice3, cs2::Direction::Backward);
    panel.resize(1060, 720);
    panel.show();
    ASSERT_TRUE(waitFor([&] {
        return railway->locomotive(Br218)->speed() == 640 && railway->locomotive(DrivenV100)->functionOn(0);
    }));
    ASSERT_TRUE(waitFor(
        [&] { return panel.throttles()[1]->directionButton()->text() == QStringLiteral("◀ Backward"); }));
    QTest::qWait(50);
    for (qsizetype i = 0; i < panel.throttles().size(); ++i) {
        ThrottleWidget* throttle = panel.throttles()[i];
        EXPECT_TRUE(throttle->isVisible());
        EXPECT_FALSE(throttle->picture()->property("placeholder").toBool()) << "the folder's picture";
        EXPECT_GE(throttle->width(), throttle->minimumSizeHint().width());
        if (i > 0) {
            EXPECT_GE(throttle->x(), panel.throttles()[i - 1]->geometry().right()) << "side by side";
        }
    }
    if (const QString dir = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR"); !dir.isEmpty()) {
        EXPECT_TRUE(panel.grab().save(dir + QStringLiteral("/throttles.png")));
        const QPalette light = QApplication::palette();
        QApplication::setPalette(darkPalette());
        ThrottlePanel dark; // the same throttles, from the settings
        dark.setRailway(railway);
        dark.resize(panel.size());
        dark.show();
        QTest::qWait(50);
        EXPECT_TRUE(dark.grab().save(dir + QStringLiteral("/throttles-dark.png")));
        QApplication::setPalette(light);
    }
}

TEST(FunctionIconsTable, MapsCs2IconNumbersToOurDrawings) {
    EXPECT_EQ(FunctionIcons::kindOf(1), FunctionKind::Light);
    EXPECT_EQ(FunctionIcons::kindOf(10), FunctionKind::Horn);
    EXPECT_EQ(FunctionIcons::kindOf(138), FunctionKind::Horn) << "bit 7 only marks a momentary key";
    EXPECT_EQ(FunctionIcons::kindOf(7), FunctionKind::Smoke);
    EXPECT_EQ(FunctionIcons::kindOf(9), FunctionKind::Coupler);
    EXPECT_EQ(FunctionIcons::kindOf(8), FunctionKind::Shunting);
    EXPECT_EQ(FunctionIcons::kindOf(20), FunctionKind::BrakeSound);
    EXPECT_EQ(FunctionIcons::kindOf(42), FunctionKind::CabLight);
    EXPECT_EQ(FunctionIcons::kindOf(52), FunctionKind::Numbered) << "50 + n is the plain key Fn";
    EXPECT_EQ(FunctionIcons::kindOf(0), FunctionKind::Numbered);
}

TEST(FunctionIconsTable, EveryDrawingIsEmbeddedAndReadable) {
    for (int kind = int(FunctionKind::Light); kind <= int(FunctionKind::Announcement); ++kind) {
        const auto k = FunctionKind(kind);
        EXPECT_FALSE(FunctionIcons::icon(k, Qt::black, 24).isNull())
            << FunctionIcons::resourcePath(k).toStdString();
        EXPECT_NE(FunctionIcons::name(k), FunctionIcons::name(FunctionKind::Numbered));
    }
    EXPECT_TRUE(FunctionIcons::icon(FunctionKind::Numbered, Qt::black, 24).isNull());
}

// The contrast of the pixel of `key` that stands out most from the key's fill: its drawing (or text).
double strongestKeyContrast(QToolButton* key) {
    const QImage image = key->grab().toImage();
    const QColor fill = mostFrequentColour(image);
    double strongest = 1.0;
    for (int y = 4; y < image.height() - 4; ++y)
        for (int x = 4; x < image.width() - 4; ++x)
            strongest = std::max(strongest, Contrast::ratio(image.pixelColor(x, y), fill));
    return strongest;
}

// Issue 32: icons drawn while the pad was greyed took the pale disabled grey and kept it; a language
// switch drew them again in black. Every drawing now has its colours whenever it is drawn.
TEST_F(ThrottleTest, FunctionIconsLookTheSameAfterALanguageSwitch) {
    constexpr int Sound = 1; // V 100's F1: an "off" key with a drawing
    throttle.resize(throttle.sizeHint());
    throttle.show();
    QTest::qWait(20);
    ASSERT_NE(key(Sound), nullptr);
    ASSERT_FALSE(key(Sound)->isChecked());
    const QImage english = throttle.functions()->grab().toImage();
    EXPECT_GE(strongestKeyContrast(key(Sound)), Contrast::ForText) << "the drawing reads on its key";
    ASSERT_TRUE(translations.select(Language::German));
    QEvent change(QEvent::LanguageChange);
    QApplication::sendEvent(throttle.functions(), &change);
    QTest::qWait(20);
    EXPECT_EQ(throttle.directionButton()->text(), QStringLiteral("Vorwärts ▶")) << "switched";
    const QImage german = throttle.functions()->grab().toImage();
    EXPECT_EQ(german, english);
    ASSERT_TRUE(translations.select(Language::English));
}

// Greyed keys (state not reported) are paler than usable ones, never darker, and still readable.
TEST_F(ThrottleTest, GreyedFunctionKeysArePalerYetReadable) {
    constexpr int Sound = 1;
    railways.railway()->setFunction(DrivenV100, 0, true);
    ASSERT_TRUE(waitFor([&] { return key(0)->isChecked(); }));
    throttle.resize(throttle.sizeHint());
    throttle.show();
    QTest::qWait(20);
    const double usableOff = strongestKeyContrast(key(Sound));
    const QColor usableOnFill = mostFrequentColour(key(0)->grab().toImage());
    testStation.stop();
    ASSERT_TRUE(waitFor([&] { return !railways.railway()->isStateReported(); }));
    ASSERT_FALSE(key(Sound)->isEnabled());
    ASSERT_TRUE(key(0)->isChecked()) << "on, as the station last said";
    QTest::qWait(20);
    const double greyedOff = strongestKeyContrast(key(Sound));
    EXPECT_LT(greyedOff, usableOff) << "paler than a usable key";
    EXPECT_GE(greyedOff, Contrast::ForText) << "yet readable";
    const QColor button = throttle.functions()->palette().color(QPalette::Active, QPalette::Button);
    const QColor greyedOnFill = mostFrequentColour(key(0)->grab().toImage());
    EXPECT_LT(Contrast::ratio(greyedOnFill, button), Contrast::ratio(usableOnFill, button))
        << "a greyed key that is on stands out less than a usable one: " << greyedOnFill.name().toStdString()
        << " " << usableOnFill.name().toStdString();
    EXPECT_GE(strongestKeyContrast(key(0)), Contrast::ForText);
    if (const QString dir = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR"); !dir.isEmpty()) {
        EXPECT_TRUE(throttle.grab().save(dir + QStringLiteral("/throttle-not-reported.png")));
    }
}
