// The mouse wheel over a control panel: a picker, slider or spin box that the user did not focus lets the
// wheel scroll the panel instead of changing its value; a focused one still takes it.

#include "common/WheelGuard.h"

#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <QtTest/qtestspontaneevent.h>
#include <gtest/gtest.h>

using namespace stellwerk::ui;

namespace {

// One notch down, as a mouse sends it: spontaneous, so that Qt gives wheel focus and passes an ignored
// wheel on to the parents as it does for a real one.
void turnWheelDown(QWidget* target) {
    const QPointF local = QRectF(target->rect()).center();
    QWheelEvent wheel(local, target->mapToGlobal(local), QPoint(),
                      QPoint(0, -QWheelEvent::DefaultDeltasPerStep), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QSpontaneKeyEvent::setSpontaneous(&wheel);
    QApplication::instance()->notify(target, &wheel);
}

// A panel taller than its scroll area with a picker, a slider and a spin box in the middle.
class WheelGuardTest : public ::testing::Test {
protected:
    void SetUp() override {
        panel = new QWidget;
        auto* layout = new QVBoxLayout(panel);
        other = new QLineEdit(panel);
        layout->addWidget(other);
        picker = new QComboBox(panel);
        picker->addItems(
            {QStringLiteral("V 100 2023"), QStringLiteral("BR 218 Ost"), QStringLiteral("ICE 3")});
        layout->addWidget(picker);
        slider = new QSlider(Qt::Horizontal, panel);
        slider->setRange(0, 100);
        layout->addWidget(slider);
        spin = new QSpinBox(panel);
        spin->setRange(0, 255);
        layout->addWidget(spin);
        layout->addSpacing(1200);
        area.setWidgetResizable(true);
        area.setWidget(panel);
        area.resize(300, 240);
    }

    void showAndFocusOther() {
        area.show();
        area.activateWindow();
        ASSERT_TRUE(QTest::qWaitForWindowActive(&area));
        other->setFocus();
        ASSERT_TRUE(other->hasFocus());
    }
    int scrolled() const { return area.verticalScrollBar()->value(); }

    QScrollArea area;
    QWidget* panel = nullptr;
    QLineEdit* other = nullptr;
    QComboBox* picker = nullptr;
    QSlider* slider = nullptr;
    QSpinBox* spin = nullptr;
};

} // namespace

TEST_F(WheelGuardTest, WithoutTheGuardTheWheelChangesAnUnfocusedPicker) {
    showAndFocusOther();
    turnWheelDown(picker);
    EXPECT_EQ(picker->currentIndex(), 1) << "Qt's own behaviour, which the guard is there to stop";
    EXPECT_FALSE(WheelGuard::guards(picker));
}

TEST_F(WheelGuardTest, UnfocusedControlsIgnoreTheWheelAndThePanelScrolls) {
    WheelGuard::guard(panel);
    showAndFocusOther();
    int before = scrolled();
    turnWheelDown(picker);
    EXPECT_EQ(picker->currentIndex(), 0);
    EXPECT_FALSE(picker->hasFocus()) << "the wheel gives the picker no focus";
    EXPECT_GT(scrolled(), before) << "the scroll area took the wheel";
    before = scrolled();
    turnWheelDown(slider);
    EXPECT_EQ(slider->value(), 0);
    EXPECT_GT(scrolled(), before);
    before = scrolled();
    turnWheelDown(spin);
    EXPECT_EQ(spin->value(), 0);
    EXPECT_GT(scrolled(), before);
}

TEST_F(WheelGuardTest, AFocusedControlStillTakesTheWheel) {
    WheelGuard::guard(panel);
    showAndFocusOther();
    picker->setFocus();
    const int before = scrolled();
    turnWheelDown(picker);
    EXPECT_EQ(picker->currentIndex(), 1);
    spin->setFocus();
    turnWheelDown(spin);
    EXPECT_EQ(spin->value(), 0) << "down from the lowest value stays there";
    spin->setValue(10);
    turnWheelDown(spin);
    EXPECT_EQ(spin->value(), 9);
    slider->setFocus();
    slider->setValue(50);
    turnWheelDown(slider);
    EXPECT_LT(slider->value(), 50);
    EXPECT_EQ(scrolled(), before) << "a focused control keeps the wheel to itself";
}

TEST_F(WheelGuardTest, AControlAddedLaterIsGuardedToo) {
    WheelGuard::guard(panel);
    auto* later = new QComboBox(panel);
    later->addItems({QStringLiteral("MM2"), QStringLiteral("DCC")});
    panel->layout()->addWidget(later);
    showAndFocusOther();
    EXPECT_TRUE(WheelGuard::guards(later));
    EXPECT_NE(later->focusPolicy(), Qt::WheelFocus);
    turnWheelDown(later);
    EXPECT_EQ(later->currentIndex(), 0);
    EXPECT_FALSE(later->hasFocus());
}

TEST_F(WheelGuardTest, ScrollBarsKeepTheWheel) {
    WheelGuard::guard(panel);
    showAndFocusOther();
    EXPECT_FALSE(WheelGuard::guards(area.verticalScrollBar()));
    EXPECT_FALSE(WheelGuard::guards(other));
}
