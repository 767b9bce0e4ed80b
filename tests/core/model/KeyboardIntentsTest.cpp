// Document 4.1 and 2.12 for the keyboard and the settings page: switching a keyboard number that no
// article uses, the end of every switching, and writing a device's configuration channel.

#include "ModelBench.h"
#include "sim/StatusChannels.h"

namespace stellwerk::model::test {
namespace {

constexpr std::uint8_t PowerSupplyChannel = 5;  // the simulated CS2's list channel
constexpr std::uint8_t CurrentLimitChannel = 6; // its number channel, 500..4500 (0.5..4.5 A)

class KeyboardIntents : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(bench.start()); }

    const Device& cs2() const { return *bench.railway.device(CentralStationUid); }

    ModelBench bench;
};

TEST_F(KeyboardIntents, AnAddressWithoutArticleSwitchesAsMm2) {
    QSignalSpy addresses(&bench.railway, &Railway::addressesChanged);
    QSignalSpy ended(&bench.railway, &Railway::switchingEnded);
    EXPECT_FALSE(bench.railway.addressPosition(20));
    bench.railway.switchAddress(20, 1);
    ASSERT_TRUE(waitFor([&] { return bench.railway.addressPosition(20) == 1; }));
    EXPECT_EQ(bench.station.accessoryPosition(0x3013), 1) << "keyboard 20 is Loc-ID 0x3000 + 19";
    ASSERT_GE(addresses.count(), 1);
    EXPECT_EQ(addresses.first().at(0).value<QList<qint64>>(), QList<qint64>{20});
    ASSERT_TRUE(waitFor([&] { return ended.count() == 1; }));
    EXPECT_EQ(ended.first().at(0).toLongLong(), 20);
    EXPECT_EQ(ended.first().at(1).toInt(), 1);
    EXPECT_TRUE(ended.first().at(2).toBool());
}

TEST_F(KeyboardIntents, AnAddressOutsideTheMm2RangeIsAProblem) {
    QSignalSpy problems(&bench.railway, &Railway::problem);
    QSignalSpy ended(&bench.railway, &Railway::switchingEnded);
    bench.railway.switchAddress(0, 1);
    bench.railway.switchAddress(20, 2);
    ASSERT_EQ(problems.count(), 2);
    EXPECT_TRUE(problems.at(1).at(0).toString().contains("Address 20: output 2"))
        << problems.at(1).at(0).toString().toStdString();
    ASSERT_EQ(ended.count(), 2);
    EXPECT_FALSE(ended.at(1).at(2).toBool());
}

TEST_F(KeyboardIntents, SwitchingAnArticleEndsAcknowledged) {
    QSignalSpy ended(&bench.railway, &Railway::switchingEnded);
    bench.railway.switchAccessory(5, 1);
    ASSERT_TRUE(waitFor([&] { return ended.count() == 1; }));
    EXPECT_EQ(ended.first().at(0).toLongLong(), 5);
    EXPECT_TRUE(ended.first().at(2).toBool());
    EXPECT_EQ(bench.railway.accessory(5)->position(), 1);
}

TEST_F(KeyboardIntents, TheStationDescribesItsSettings) {
    ASSERT_EQ(cs2().settings().size(), 2u);
    const DeviceSetting* supply = cs2().setting(PowerSupplyChannel);
    ASSERT_NE(supply, nullptr);
    EXPECT_TRUE(supply->isList());
    EXPECT_EQ(supply->options().size(), 3);
    EXPECT_EQ(supply->value(), 2);
    const DeviceSetting* limit = cs2().setting(CurrentLimitChannel);
    ASSERT_NE(limit, nullptr);
    EXPECT_TRUE(limit->isNumber());
    EXPECT_EQ(limit->minimum(), 500);
    EXPECT_EQ(limit->maximum(), 4500);
    EXPECT_EQ(limit->decimals(), 3);
    EXPECT_EQ(limit->unit(), QStringLiteral("A"));
    EXPECT_DOUBLE_EQ(limit->scaled(4000), 4.0);
    EXPECT_EQ(limit->rawFor(2.5), 2500);
}

TEST_F(KeyboardIntents, AnAcceptedSettingIsReadBackFromTheDevice) {
    QSignalSpy configured(&bench.railway, &Railway::deviceConfigured);
    bench.railway.configureDevice(CentralStationUid, CurrentLimitChannel, 2500);
    ASSERT_TRUE(waitFor([&] { return configured.count() == 1; }));
    EXPECT_EQ(configured.first().at(2).value<SettingResult>(), SettingResult::Accepted);
    EXPECT_EQ(bench.station.statusChannels().setting(CurrentLimitChannel), 2500);
    EXPECT_TRUE(waitFor([&] { return cs2().setting(CurrentLimitChannel)->value() == 2500; }));
}

TEST_F(KeyboardIntents, AValueOutsideTheRangeIsRefusedWithoutSending) {
    QSignalSpy configured(&bench.railway, &Railway::deviceConfigured);
    QSignalSpy problems(&bench.railway, &Railway::problem);
    bench.railway.configureDevice(CentralStationUid, PowerSupplyChannel, 3);
    ASSERT_EQ(configured.count(), 1);
    EXPECT_EQ(configured.first().at(2).value<SettingResult>(), SettingResult::Refused);
    EXPECT_EQ(problems.count(), 1);
    EXPECT_EQ(bench.station.statusChannels().setting(PowerSupplyChannel), 2);
}

TEST_F(KeyboardIntents, ASilentDeviceGivesNoAnswer) {
    QObject::disconnect(&bench.stationEnd, &transport::Transport::framesReceived, &bench.station, nullptr);
    QSignalSpy configured(&bench.railway, &Railway::deviceConfigured);
    bench.railway.configureDevice(CentralStationUid, PowerSupplyChannel, 0);
    ASSERT_TRUE(waitFor([&] { return configured.count() == 1; }));
    EXPECT_EQ(configured.first().at(2).value<SettingResult>(), SettingResult::NoAnswer);
    EXPECT_EQ(cs2().setting(PowerSupplyChannel)->value(), 2);
}

} // namespace
} // namespace stellwerk::model::test
