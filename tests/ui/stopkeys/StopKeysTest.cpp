// The keys that stop the layout, and the one that must not: Escape closes a popup or a dialog and does
// nothing else (seen: cancelling Connect... with Escape cut the track power); Space, the STOP key and the
// extra STOP key stop. Asserted on the wire (the stop frames written) and on the simulated station.

#include "stopkeys/EmergencyStopKeys.h"
#include "stopkeys/StopKeyMenu.h"
#include "stopkeys/StopKeySettings.h"
#include "support/TrustTestSupport.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QMenu>
#include <QTableView>
#include <QTimer>
#include <functional>

using namespace stellwerk;
using namespace stellwerk::ui;
using station::PowerState;
using SimPower = sim::SimulatedStation::Power;

namespace {

constexpr int SettleMs = 300; // a stop would have reached the wire and been confirmed by now

class StopKeysTest : public test::DeskOnTestStation {
protected:
    // Makes `window` the active one with the keyboard in it, as a click into it would.
    static bool activate(QWidget* top) {
        top->activateWindow();
        QApplication::setActiveWindow(top);
        return QTest::qWaitFor(
            [top] { return QApplication::focusWidget() && QApplication::focusWidget()->window() == top; },
            2000);
    }
    // Opens Station → Connect… and runs `inside` with the dialog once it is up and has the keyboard.
    void whileConnectDialogIsOpen(const std::function<void(QDialog*)>& inside) {
        bool ran = false;
        QTimer::singleShot(8000, window.get(), [] { // never hang on a failed assertion inside
            if (QWidget* modal = QApplication::activeModalWidget())
                modal->close();
        });
        QTimer::singleShot(0, window.get(), [&] {
            auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
            ASSERT_NE(dialog, nullptr);
            ASSERT_TRUE(activate(dialog));
            inside(dialog);
            ran = true;
            if (dialog->isVisible())
                dialog->reject();
        });
        window->showConnectDialog();
        EXPECT_TRUE(ran);
    }
};

} // namespace

TEST_F(StopKeysTest, EscapeInTheConnectDialogCancelsItAndSendsNoStop) {
    test::WireWatch wire(connection);
    const QString address = connection.address();
    bool closed = false;
    whileConnectDialogIsOpen([&](QDialog* dialog) {
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape);
        closed = !dialog->isVisible() && dialog->result() == QDialog::Rejected;
    });
    EXPECT_TRUE(closed);
    QTest::qWait(SettleMs);
    EXPECT_EQ(wire.stops(), 0);
    EXPECT_EQ(power(), PowerState::Running);
    EXPECT_EQ(server.station().power(), SimPower::Running);
    EXPECT_EQ(connection.address(), address);
    EXPECT_EQ(connection.state(), connection::StationConnection::State::Ready);
}

TEST_F(StopKeysTest, TheExtraStopKeyStopsEvenFromADialog) {
    test::WireWatch wire(connection);
    whileConnectDialogIsOpen([](QDialog*) { QTest::keyClick(QApplication::focusWidget(), Qt::Key_F12); });
    ASSERT_TRUE(powerBecomes(PowerState::Stopped));
    EXPECT_EQ(wire.stops(), 1);
    EXPECT_EQ(server.station().power(), SimPower::Stopped);
}

TEST_F(StopKeysTest, EscapeOnTheMainWindowWithNothingOpenStops) {
    test::WireWatch wire(connection);
    auto* table = window->findChild<QTableView*>(QStringLiteral("locomotiveTable"));
    ASSERT_NE(table, nullptr);
    ASSERT_TRUE(activate(window.get()));
    table->setFocus(Qt::MouseFocusReason);
    QTest::keyClick(table, Qt::Key_Escape);
    ASSERT_TRUE(powerBecomes(PowerState::Stopped));
    EXPECT_EQ(wire.stops(), 1);
}

TEST_F(StopKeysTest, EscapeWithAMenuOpenClosesItAndDoesNotStop) {
    test::WireWatch wire(connection);
    ASSERT_TRUE(activate(window.get()));
    auto* menu = window->findChild<QMenu*>(QStringLiteral("stationMenu"));
    ASSERT_NE(menu, nullptr);
    menu->popup(window->mapToGlobal(QPoint(40, 40)));
    ASSERT_TRUE(QTest::qWaitFor([menu] { return QApplication::activePopupWidget() == menu; }, 2000));
    QTest::keyClick(menu, Qt::Key_Escape);
    EXPECT_TRUE(QTest::qWaitFor([menu] { return !menu->isVisible(); }, 2000));
    QTest::qWait(SettleMs);
    EXPECT_EQ(wire.stops(), 0);
    EXPECT_EQ(power(), PowerState::Running);
}

TEST_F(StopKeysTest, SpaceStillStopsFromATable) {
    test::WireWatch wire(connection);
    auto* table = window->findChild<QTableView*>(QStringLiteral("locomotiveTable"));
    ASSERT_TRUE(activate(window.get()));
    table->setFocus(Qt::MouseFocusReason);
    QTest::keyClick(table, Qt::Key_Space);
    ASSERT_TRUE(powerBecomes(PowerState::Stopped));
    EXPECT_EQ(wire.stops(), 1);
}

TEST_F(StopKeysTest, TheExtraStopKeyIsChosenInTheStationMenuAndRemembered) {
    auto* keys = window->findChild<StopKeyMenu*>(QStringLiteral("stopKeyMenu"));
    ASSERT_NE(keys, nullptr);
    EXPECT_EQ(keys->current(), Qt::Key_F12);
    auto* pause = keys->findChild<QAction*>(QStringLiteral("stopKey_%1").arg(int(Qt::Key_Pause)));
    ASSERT_NE(pause, nullptr);
    pause->trigger();
    EXPECT_EQ(window->stopKeys()->extraKey(), Qt::Key_Pause);
    EXPECT_EQ(StopKeySettings::load(), Qt::Key_Pause);
    const auto* stop = window->findChild<QAction*>(QStringLiteral("stopAction"));
    EXPECT_TRUE(stop->text().endsWith(QStringLiteral("Space, Pause"))) << stop->text().toStdString();

    test::WireWatch wire(connection);
    ASSERT_TRUE(activate(window.get()));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_F12);
    QTest::qWait(SettleMs);
    EXPECT_EQ(wire.stops(), 0) << "F12 is no STOP key any more";
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Pause);
    ASSERT_TRUE(powerBecomes(PowerState::Stopped));
    EXPECT_EQ(wire.stops(), 1);
}
