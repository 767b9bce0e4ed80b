// The Devices panel as a person uses it (issue 15): it lists the RO module and the OpenRailCAN devices
// with their state, switches a relay and shows it on only once the module confirmed it, switches all
// relays off, shows inputs live, and says "not reported" while the module is away, without switching
// anything later when it is back. What reached the module is read from the simulated module itself.

#include "devices/DevicesRig.h"
#include "devices/OrcDeviceView.h"
#include "devices/RoModuleView.h"
#include "devices/SignalGrid.h"

#include <QLabel>
#include <QPushButton>
#include <QToolButton>

namespace stellwerk::ui::test {
namespace {

using Column = DeviceTableModel::Column;

class DevicesPanelTest : public DevicesRig {
protected:
    void SetUp() override {
        DevicesRig::SetUp();
        if (HasFatalFailure())
            return;
        panel->selectRow(rowOfModule());
        ASSERT_TRUE(waitUntil([&] { return relays().state(1).has_value(); }));
    }
    SignalGrid& relays() const { return panel->moduleView().relays(); }
    SignalGrid& inputs() const { return panel->moduleView().inputs(); }
    void click(int relay) { QTest::mouseClick(relays().cell(relay), Qt::LeftButton); }

    // The module stops answering while a relay is asked for: the relay is never shown on, the module becomes
    // "offline" and its relays "not reported"; back after `away`, it is read again and what was asked for
    // while it was away is not switched behind the person's back.
    void goesAwayAndComesBack(std::chrono::milliseconds away) {
        module.unplug();
        QTest::mouseClick(relays().cell(4), Qt::LeftButton);
        ASSERT_TRUE(waitUntil([&] { return !relays().state(4).has_value(); }));
        EXPECT_FALSE(module.relay(4));
        EXPECT_FALSE(relays().cell(4)->isEnabled()) << "nothing to switch while it does not answer";
        EXPECT_TRUE(panel->moduleView().stateText().startsWith(QStringLiteral("Offline")))
            << panel->moduleView().stateText().toStdString();
        EXPECT_NE(panel->summaryText().indexOf(QStringLiteral("RO modules: 0 of 1 online.")), -1);
        EXPECT_FALSE(panel->moduleView().allOff().isEnabled());
        QTest::qWait(int(away.count()));
        const std::size_t writesBefore = module.writes().size();
        module.plugIn();
        ASSERT_TRUE(waitUntil([&] { return relays().state(4).has_value(); }, 15000));
        EXPECT_EQ(relays().state(4), false);
        EXPECT_FALSE(module.relay(4)) << "the click made while it was away never reaches it";
        EXPECT_EQ(module.writes().size(), writesBefore);
    }
};

TEST_F(DevicesPanelTest, ListsTheModuleAndTheOpenRailCanDevicesWithTheirState) {
    ASSERT_EQ(panel->table().rowCount(), 3);
    EXPECT_EQ(cell(0, Column::Name), QStringLiteral("RO 1")) << "the modules come first";
    EXPECT_EQ(cell(0, Column::State), QStringLiteral("online"));
    EXPECT_EQ(cell(0, Column::Kind), QStringLiteral("RO module, 16 relays, 29-bit"));
    EXPECT_EQ(cell(0, Column::Address), QStringLiteral("bus 1: 0x01FE0001 / 0x01FF0001"));
    const int decoderRow = panel->table().rowOf({true, DecoderUid, {}});
    ASSERT_GE(decoderRow, 0);
    EXPECT_EQ(cell(decoderRow, Column::Name), QStringLiteral("0x3A2E0007"));
    EXPECT_EQ(cell(decoderRow, Column::Kind), QStringLiteral("OpenRailCAN decoder"));
    EXPECT_EQ(cell(decoderRow, Column::Address), QStringLiteral("bus id 0x0007"));
    EXPECT_EQ(relays().count(), 16);
    EXPECT_EQ(inputs().count(), 16);

    ASSERT_TRUE(translations.select(Language::German));
    EXPECT_EQ(cell(0, Column::State), QStringLiteral("online"));
    EXPECT_EQ(cell(0, Column::Kind), QStringLiteral("RO-Modul, 16 Relais, 29 Bit"));
    EXPECT_EQ(cell(decoderRow, Column::Kind), QStringLiteral("OpenRailCAN-Dekoder"));
    EXPECT_EQ(panel->summaryText(),
              QStringLiteral("OpenRailCAN: 2 von 2 Geräten online. RO-Module: 1 von 1 online."));
}

TEST_F(DevicesPanelTest, AClickedRelayIsSwitchedOnTheModuleAndShownOnOnceItConfirmed) {
    ASSERT_EQ(relays().state(3), false);
    click(3);
    EXPECT_TRUE(relays().isWaiting(3)) << "asked for, not yet confirmed";
    EXPECT_EQ(relays().state(3), false) << "nothing is shown switched before the module says OK";
    EXPECT_FALSE(relays().cell(3)->isEnabled()) << "no second click while the first is under way";
    ASSERT_TRUE(waitUntil([&] { return relays().state(3) == true; }));
    EXPECT_TRUE(module.relay(3));
    EXPECT_FALSE(relays().isWaiting(3));
    ASSERT_EQ(module.writes().size(), 1u) << "one write, not one per repaint";

    click(3);
    ASSERT_TRUE(waitUntil([&] { return relays().state(3) == false; }));
    EXPECT_FALSE(module.relay(3));
}

TEST_F(DevicesPanelTest, AllOffSwitchesEveryRelayOff) {
    for (const int relay : {1, 5, 16}) {
        click(relay);
        ASSERT_TRUE(waitUntil([&] { return relays().state(relay) == true; })) << relay;
    }
    ASSERT_EQ(module.relays(), 0b1000'0000'0001'0001u);
    ASSERT_TRUE(panel->moduleView().allOff().isEnabled());
    QTest::mouseClick(&panel->moduleView().allOff(), Qt::LeftButton);
    ASSERT_TRUE(waitUntil([&] { return module.relays() == 0; }))
        << module.relays() << " " << module.writes().size() << " "
        << panel->moduleView().findChild<QLabel*>(QStringLiteral("moduleProblem"))->text().toStdString();
    ASSERT_TRUE(waitUntil([&] { return relays().state(1) == false && relays().state(16) == false; }));
    for (int relay = 1; relay <= 16; ++relay)
        EXPECT_EQ(relays().state(relay), false) << relay;
}

TEST_F(DevicesPanelTest, InputsAreShownLive) {
    ASSERT_EQ(inputs().state(2), false);
    module.setInput(2, true);
    ASSERT_TRUE(waitUntil([&] { return inputs().state(2) == true; }));
    module.setInput(2, false);
    ASSERT_TRUE(waitUntil([&] { return inputs().state(2) == false; }));
    EXPECT_EQ(inputs().state(1), false);
}

TEST_F(DevicesPanelTest, AModuleAwayForASecondIsNotReportedAndSwitchesNothingLater) {
    goesAwayAndComesBack(std::chrono::seconds(1));
}

TEST_F(DevicesPanelTest, AModuleAwayForTwentySecondsIsNotReportedAndSwitchesNothingLater) {
    goesAwayAndComesBack(std::chrono::seconds(20));
}

// The gateway of the device bus is unplugged: the module's row says its bus is not connected, the
// OpenRailCAN devices leave the table with their central, and nothing is shown as on; plugged in again,
// everything is read afresh.
TEST_F(DevicesPanelTest, ABusThatGoesAwaySaysSoAndComesBackReadAfresh) {
    click(2);
    ASSERT_TRUE(waitUntil([&] { return relays().state(2) == true; }));
    gateway.stop();
    ASSERT_TRUE(
        waitUntil([&] { return cell(rowOfModule(), Column::State) == QStringLiteral("bus not connected"); }));
    EXPECT_FALSE(relays().state(2).has_value()) << "what the module said before is no longer vouched for";
    EXPECT_FALSE(relays().cell(2)->isEnabled());
    EXPECT_EQ(panel->table().rowCount(), 1) << "the OpenRailCAN devices went with their central";
    EXPECT_NE(panel->summaryText().indexOf(QStringLiteral("OpenRailCAN: its bus is not connected.")), -1)
        << panel->summaryText().toStdString();
    ASSERT_TRUE(gateway.listen());
    ASSERT_TRUE(waitUntil([&] { return everythingOnline() && relays().state(2).has_value(); }, 20000))
        << panel->summaryText().toStdString();
    EXPECT_EQ(relays().state(2), true) << "read back from the module, which kept its relay";
    EXPECT_TRUE(module.relay(2));
}

// Frames on the module's answer id that are no RO answer (another program on the bus, a broken module)
// change nothing on the screen and are counted.
TEST_F(DevicesPanelTest, GarbageOnTheAnswerIdChangesNothing) {
    const romodule::RoModuleSession* session = connection.devices().roModule(QStringLiteral("RO 1"));
    ASSERT_NE(session, nullptr);
    const std::uint64_t unreadable = session->counters().malformed;
    const std::uint64_t foreign = session->counters().stale + session->counters().unsolicited;
    ro::Payload noAnswer;
    noAnswer.bytes[0] = 0x77; // no answer code
    noAnswer.size = 1;
    ro::OkAnswer otherJob;
    otherJob.job = std::uint8_t(session->nextJob() + 100); // relay 1 "on", for a job nobody asked
    otherJob.width = ro::Width::Word;
    otherJob.value = 0xFFFF;
    const ro::FrameIds ids = module.profile().ids;
    otherProgram.send({ro::frameOf(ids.answer, true, noAnswer),
                       ro::frameOf(ids.answer, true, ro::encode(ro::Answer{otherJob}))});
    ASSERT_TRUE(waitUntil([&] {
        return session->counters().malformed > unreadable &&
               session->counters().stale + session->counters().unsolicited > foreign;
    }));
    QTest::qWait(300);
    for (int relay = 1; relay <= 16; ++relay)
        EXPECT_EQ(relays().state(relay), false) << relay;
    EXPECT_EQ(module.relays(), 0u);
    EXPECT_NE(panel->summaryText().indexOf(QStringLiteral("RO modules: 1 of 1 online.")), -1);
    EXPECT_TRUE(waitUntil([&] {
        return panel->moduleView().countersText().endsWith(QStringLiteral("unreadable 1"));
    })) << panel->moduleView().countersText().toStdString();
}

TEST_F(DevicesPanelTest, AnOpenRailCanEncodersInputsAndTheDecodersOutputsAreShown) {
    const int encoderRow = panel->table().rowOf({true, EncoderUid, {}});
    panel->selectRow(encoderRow);
    SignalGrid& lamps = panel->orcView().signalGrid();
    encoder.setInput(5, true);
    ASSERT_TRUE(waitUntil([&] { return lamps.state(6) == true; })) << "input 5 is the sixth lamp";

    panel->selectRow(panel->table().rowOf({true, DecoderUid, {}}));
    EXPECT_EQ(lamps.count(), 8);
    EXPECT_FALSE(lamps.state(1).has_value())
        << "a decoder says nothing of its outputs until it confirms a switch";
    EXPECT_TRUE(panel->orcView().detailsText().contains(QStringLiteral("bus id 0x0007")));
}

} // namespace
} // namespace stellwerk::ui::test
