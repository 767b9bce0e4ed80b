// The Status page's configuration channels against the demo's simulated CS2 (document 2.12): a
// drop-down for its power supply list, a slider for its current limit; a write reaches the station, the
// station reports the new value and the page says it was accepted.

#include "sim/StatusChannels.h"
#include "status/DeviceSettingEditor.h"
#include "status/StatusPanel.h"
#include "support/KeyboardTestSupport.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QSlider>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

constexpr std::uint8_t PowerSupplyChannel = 5;
constexpr std::uint8_t CurrentLimitChannel = 6;

class DeviceSettingsTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(demo.start());
        ASSERT_TRUE(controller.connect(demo.url()));
        panel.setRailway(controller.railway());
        panel.show();
        ASSERT_TRUE(
            QTest::qWaitFor([this] { return panel.settingEditors(cs2()).size() == 2; }, test::CommandMs));
    }

    std::uint32_t cs2() { return demo.station().uid(); }
    DeviceSettingEditor& editor(std::uint8_t channel) {
        for (DeviceSettingEditor* found : panel.settingEditors(cs2()))
            if (found->channel() == channel)
                return *found;
        throw std::runtime_error("no such setting");
    }
    const model::DeviceSetting& setting(std::uint8_t channel) {
        return *controller.railway()->device(demo.station().uid())->setting(channel);
    }

    test::DemoStation demo;
    test::Controller controller;
    StatusPanel panel;
};

TEST_F(DeviceSettingsTest, ListAndNumberChannelsShowTheDevicesValues) {
    ASSERT_NE(editor(PowerSupplyChannel).list(), nullptr);
    EXPECT_EQ(editor(PowerSupplyChannel).list()->count(), 3);
    EXPECT_EQ(editor(PowerSupplyChannel).list()->currentText(), QStringLiteral("Schaltnetzteil 60101"));
    QSlider* slider = editor(CurrentLimitChannel).slider();
    ASSERT_NE(slider, nullptr);
    EXPECT_EQ(slider->minimum(), 500);
    EXPECT_EQ(slider->maximum(), 4500);
    EXPECT_EQ(slider->value(), 4000);
    EXPECT_EQ(editor(CurrentLimitChannel).number()->suffix(), QStringLiteral(" A"));
    EXPECT_DOUBLE_EQ(editor(CurrentLimitChannel).number()->value(), 4.0);
    EXPECT_EQ(editor(CurrentLimitChannel).stateText(), QString());
}

TEST_F(DeviceSettingsTest, MovingTheSliderWritesTheLimitAndShowsAccepted) {
    editor(CurrentLimitChannel).slider()->setValue(2500); // as the keyboard or a click on the groove does
    EXPECT_EQ(editor(CurrentLimitChannel).state(), DeviceSettingEditor::State::Writing);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return editor(CurrentLimitChannel).state() == DeviceSettingEditor::State::Accepted; },
        test::CommandMs));
    EXPECT_EQ(editor(CurrentLimitChannel).stateText(), QStringLiteral("accepted ✓"));
    EXPECT_EQ(demo.station().statusChannels().setting(CurrentLimitChannel), 2500);
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return setting(CurrentLimitChannel).value() == 2500; }, test::CommandMs))
        << "the station reports the new value";
    EXPECT_DOUBLE_EQ(editor(CurrentLimitChannel).number()->value(), 2.5);
}

TEST_F(DeviceSettingsTest, ChoosingAnotherPowerSupplyWritesIt) {
    QComboBox* list = editor(PowerSupplyChannel).list();
    list->setFocus();
    QTest::keyClick(list, Qt::Key_Up);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return editor(PowerSupplyChannel).state() == DeviceSettingEditor::State::Accepted; },
        test::CommandMs));
    EXPECT_EQ(demo.station().statusChannels().setting(PowerSupplyChannel), 1);
    EXPECT_TRUE(QTest::qWaitFor([&] { return setting(PowerSupplyChannel).value() == 1; }, test::CommandMs));
    EXPECT_EQ(list->currentText(), QStringLiteral("Schaltnetzteil 60061"));
}

TEST_F(DeviceSettingsTest, AValueTheDeviceCannotTakeIsRefusedAndTheOldOneShown) {
    controller.railway()->configureDevice(cs2(), CurrentLimitChannel, 9000);
    EXPECT_EQ(editor(CurrentLimitChannel).state(), DeviceSettingEditor::State::Refused);
    EXPECT_EQ(editor(CurrentLimitChannel).stateText(), QStringLiteral("refused ✗"));
    EXPECT_EQ(editor(CurrentLimitChannel).slider()->value(), 4000);
    EXPECT_EQ(demo.station().statusChannels().setting(CurrentLimitChannel), 4000);
}

TEST_F(DeviceSettingsTest, AWriteWithoutAnswerSaysSoAndShowsTheOldValue) {
    demo.stop();
    editor(CurrentLimitChannel).slider()->setValue(1500);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return editor(CurrentLimitChannel).state() == DeviceSettingEditor::State::NoAnswer; },
        test::CommandMs));
    EXPECT_EQ(editor(CurrentLimitChannel).stateText(), QStringLiteral("no answer ✗"));
    EXPECT_EQ(editor(CurrentLimitChannel).slider()->value(), 4000);
    EXPECT_EQ(setting(CurrentLimitChannel).value(), 4000);
}

} // namespace
