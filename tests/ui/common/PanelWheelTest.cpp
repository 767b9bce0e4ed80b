// Issue 32: one notch of the wheel over a throttle's locomotive picker, while scrolling the stacked
// throttles, changed which locomotive the throttle drove. On the main window every docked panel's pickers,
// sliders and spin boxes take the wheel only with focus; the wheel scrolls the panel instead.

#include "common/WheelGuard.h"
#include "devices/DevicesPanel.h"
#include "keyboard/TurnoutPanel.h"
#include "locomotives/LocomotivePanel.h"
#include "programming/ProgrammingPanel.h"
#include "shell/Workspace.h"
#include "status/StatusPanel.h"
#include "support/TrustTestSupport.h"
#include "throttle/ThrottlePanel.h"
#include "throttle/ThrottleWidget.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QWheelEvent>
#include <QtTest/qtestspontaneevent.h>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

constexpr quint32 V100 = 0x18;
constexpr quint32 Br218 = 0x4001;
constexpr quint32 Ice3 = 0x4002;

// One notch down, spontaneous as a mouse's (Qt then gives wheel focus and passes an ignored wheel up).
void wheelDown(QWidget* target) {
    const QPointF local = QRectF(target->rect()).center();
    QWheelEvent wheel(local, target->mapToGlobal(local), QPoint(),
                      QPoint(0, -QWheelEvent::DefaultDeltasPerStep), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QSpontaneKeyEvent::setSpontaneous(&wheel);
    QApplication::instance()->notify(target, &wheel);
}

// The controls a wheel would change inside `panel`.
QList<QWidget*> controlsOf(const QWidget* panel) {
    QList<QWidget*> controls;
    for (QWidget* child : panel->findChildren<QWidget*>())
        if (qobject_cast<QComboBox*>(child) || qobject_cast<QAbstractSpinBox*>(child) ||
            (qobject_cast<QAbstractSlider*>(child) && !qobject_cast<QScrollBar*>(child)))
            controls << child;
    return controls;
}

class PanelWheelTest : public test::DeskOnTestStation {};

} // namespace

TEST_F(PanelWheelTest, EveryControlPanelsControlsAreGuarded) {
    window->throttlePanel()->addThrottle(V100);
    const QList<QWidget*> panels{window->throttlePanel(), window->turnoutPanel(), window->programmingPanel(),
                                 window->statusPanel(),   window->devices(),      window->locomotivePanel()};
    for (const QWidget* panel : panels) {
        const QList<QWidget*> controls = controlsOf(panel);
        for (const QWidget* control : controls)
            EXPECT_TRUE(WheelGuard::guards(control))
                << panel->objectName().toStdString() << ": " << control->objectName().toStdString();
    }
    EXPECT_FALSE(controlsOf(window->programmingPanel()).isEmpty());
}

TEST_F(PanelWheelTest, TheWheelOverAThrottlesPickerScrollsTheThrottlesInstead) {
    ThrottlePanel* panel = window->throttlePanel();
    for (const quint32 loco : {V100, Br218, Ice3})
        panel->addThrottle(loco);
    ASSERT_TRUE(window->workspace()->showPanel(panel));
    window->activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(window.get()));
    auto* scroll = panel->findChild<QScrollArea*>();
    ASSERT_NE(scroll, nullptr);
    ASSERT_TRUE(QTest::qWaitFor([&] { return scroll->verticalScrollBar()->maximum() > 0; }, CommandMs))
        << "the throttles are stacked and scroll";
    ThrottleWidget* first = panel->throttles().first();
    QComboBox* picker = first->locomotiveChoice();
    ASSERT_TRUE(picker->isVisible());
    panel->throttles().last()->setFocus(); // the keyboard is on another throttle
    const int before = scroll->verticalScrollBar()->value();
    wheelDown(picker);
    EXPECT_EQ(first->locomotive(), V100) << "the wheel did not pick another locomotive";
    EXPECT_EQ(picker->currentData().toUInt(), V100);
    EXPECT_GT(scroll->verticalScrollBar()->value(), before) << "the throttles scrolled";
    QSlider* speed = panel->throttles()[1]->speedSlider();
    scroll->ensureWidgetVisible(speed);
    wheelDown(speed);
    EXPECT_EQ(speed->value(), 0) << "nor a speed";
    EXPECT_EQ(railway()->locomotive(Br218)->speed(), 0);
}
