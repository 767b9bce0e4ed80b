// Document 6.2 and 2.12: the devices' gauges, read on a timer with system status 0x0B and scaled by
// their status data descriptions; an overload report (2.11) is a problem a person sees.

#include "ModelBench.h"

namespace stellwerk::model::test {
namespace {

const StatusChannel& channelNamed(const Device& device, const QString& name) {
    for (const StatusChannel& channel : device.channels())
        if (channel.name() == name)
            return channel;
    throw std::runtime_error("no such channel");
}

class DeviceReadings : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(bench.start());
        bench.railway.readings().setInterval(100ms);
    }

    const Device& cs2() const { return *bench.railway.device(CentralStationUid); }

    ModelBench bench;
};

TEST_F(DeviceReadings, ThePollerReadsEveryDescribedChannel) {
    EXPECT_TRUE(bench.railway.readings().running());
    EXPECT_EQ(bench.railway.readings().sources().size(), 4u);
    ASSERT_TRUE(waitFor([&] {
        for (const StatusChannel& channel : cs2().channels())
            if (!channel.raw())
                return false;
        return true;
    }));
    const StatusChannel& volt = channelNamed(cs2(), "VOLT");
    EXPECT_DOUBLE_EQ(*volt.value(), volt.description().scaled(*volt.raw()));
    EXPECT_GT(*volt.value(), 0.0);
    EXPECT_TRUE(volt.text().endsWith(" V")) << volt.text().toStdString();
}

TEST_F(DeviceReadings, TheTrackCurrentFollowsTheLoad) {
    bench.railway.go();
    ASSERT_TRUE(waitFor([&] { return bench.railway.power() == station::PowerState::Running; }));
    bench.station.setTrackLoad(1200);
    QSignalSpy devices(&bench.railway, &Railway::devicesChanged);
    ASSERT_TRUE(waitFor([&] {
        const auto value = channelNamed(cs2(), "HGL").value();
        return value && std::abs(*value - 1.2) < 0.01;
    }));
    EXPECT_GE(devices.count(), 1);
    EXPECT_EQ(channelNamed(cs2(), "HGL").text(), "1.200 A");
}

TEST_F(DeviceReadings, AnOverloadIsAProblemAndTheTrackPowerGoesOff) {
    QSignalSpy overloaded(&bench.railway, &Railway::overloaded);
    QSignalSpy problems(&bench.railway, &Railway::problem);
    bench.railway.go();
    ASSERT_TRUE(waitFor([&] { return bench.railway.power() == station::PowerState::Running; }));
    bench.station.setTrackLoad(9000);
    ASSERT_TRUE(waitFor([&] { return overloaded.count() == 1; }));
    EXPECT_EQ(overloaded.first().at(0).toUInt(), CentralStationUid);
    ASSERT_GE(problems.count(), 1);
    EXPECT_TRUE(problems.first().at(0).toString().startsWith("Overload"))
        << problems.first().at(0).toString().toStdString();
}

TEST_F(DeviceReadings, AChannelWithoutAnswerIsShownAsOld) {
    ASSERT_TRUE(waitFor([&] { return channelNamed(cs2(), "TEMP").raw().has_value(); }));
    bench.stationEnd.close();
    ASSERT_TRUE(waitFor([&] { return channelNamed(cs2(), "TEMP").stale(); }));
    EXPECT_TRUE(channelNamed(cs2(), "TEMP").raw().has_value()) << "the last value stays";
}

// Field notes: the real Gleisbox 60113's figures.
TEST(StatusChannel, ScalesTheGleisboxVoltage) {
    station::ReadingChannel volt;
    volt.channel = 3;
    volt.power = -2;
    volt.rangeEnds = {0x039D, 0x04B2, 0x0A1E, 0x0C49};
    volt.startLabel = "10.00";
    volt.endLabel = "27.00";
    volt.unit = "Volt";
    StatusChannel channel(volt);
    EXPECT_EQ(channel.text(), "–");
    EXPECT_TRUE(channel.confirm(2177, QDateTime::currentDateTime()));
    EXPECT_NEAR(*channel.value(), 21.8, 0.05);
    EXPECT_EQ(channel.text(), QString::number(*channel.value(), 'f', 2) + " Volt")
        << "decimals as the labels";
    EXPECT_DOUBLE_EQ(channel.minimum(), 10.0);
    EXPECT_DOUBLE_EQ(channel.maximum(), 27.0);
}

} // namespace
} // namespace stellwerk::model::test
