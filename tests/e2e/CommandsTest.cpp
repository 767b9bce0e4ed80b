// Every command the app sends is acknowledged by the simulated CS2, over TCP, UDP and a virtual CAN bus,
// through the session's CommandTracker; the station's state shows that it was carried out. One test per
// command of the protocol document.

#include "E2eSupport.h"
#include "station/DeviceDescription.h"

namespace stellwerk::e2e {
namespace {

using Status = CommandResult::Status;

class AcknowledgedCommand : public ::testing::TestWithParam<Wire> {
protected:
    void SetUp() override { ASSERT_TRUE(rig_.start()) << "the station did not answer a ping"; }

    // Acknowledged, and the answer's body as the expected type.
    template <class Body>
    std::optional<Body> acknowledged(const cs2::MessageBody& body) {
        const CommandResult result = rig_.acknowledge(command(body));
        EXPECT_EQ(result.status, Status::Acknowledged) << station::commandStatusName(result.status);
        if (!result.succeeded() || !result.answer)
            return std::nullopt;
        const auto* answer = std::get_if<Body>(&result.answer->body);
        return answer ? std::optional<Body>(*answer) : std::nullopt;
    }

    const sim::SimulatedLoco* loco(std::uint32_t locId) const { return rig_.station.loco(locId); }

    Rig rig_{GetParam()};
};

// 2.2 and 2.1: GO switches the track on, STOP off again.
TEST_P(AcknowledgedCommand, SystemGoAndStop) {
    ASSERT_TRUE(acknowledged<cs2::SystemGo>(cs2::SystemGo{0}));
    EXPECT_EQ(rig_.station.power(), sim::TrackPower::Running);
    ASSERT_TRUE(acknowledged<cs2::SystemStop>(cs2::SystemStop{0}));
    EXPECT_EQ(rig_.station.power(), sim::TrackPower::Stopped);
}

// 2.3: HALT stops every loco; the track stays on.
TEST_P(AcknowledgedCommand, SystemHalt) {
    ASSERT_TRUE(acknowledged<cs2::SystemGo>(cs2::SystemGo{0}));
    ASSERT_TRUE(acknowledged<cs2::SystemHalt>(cs2::SystemHalt{0}));
    EXPECT_EQ(rig_.station.power(), sim::TrackPower::Halted);
}

// 3.4: a speed for the mfx, MM2 and DCC loco of the demo layout.
TEST_P(AcknowledgedCommand, LocoSpeedOfEveryDecoderProtocol) {
    std::uint16_t speed = 300;
    for (std::uint32_t locId : {MfxLoco, Mm2Loco, DccLoco}) {
        speed = std::uint16_t(speed + 100);
        const auto answer = acknowledged<cs2::LocoSpeed>(cs2::LocoSpeed{cs2::LocId(locId), speed});
        ASSERT_TRUE(answer) << std::hex << locId;
        EXPECT_EQ(answer->speed, speed);
        ASSERT_NE(loco(locId), nullptr);
        EXPECT_EQ(loco(locId)->speed, speed);
    }
}

// 3.4: a query (DLC 4) is answered with the speed the station runs the loco at.
TEST_P(AcknowledgedCommand, LocoSpeedQueryAnswersTheStationsSpeed) {
    ASSERT_TRUE(acknowledged<cs2::LocoSpeed>(cs2::LocoSpeed{cs2::LocId(MfxLoco), 640}));
    const auto answer = acknowledged<cs2::LocoSpeed>(cs2::LocoSpeed{cs2::LocId(MfxLoco), std::nullopt});
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->speed, 640);
}

// 3.5: the direction of each; the station also sets the speed to 0 (field notes).
TEST_P(AcknowledgedCommand, LocoDirectionOfEveryDecoderProtocol) {
    const auto backward = std::uint8_t(cs2::Direction::Backward);
    for (std::uint32_t locId : {MfxLoco, Mm2Loco, DccLoco}) {
        ASSERT_TRUE(acknowledged<cs2::LocoSpeed>(cs2::LocoSpeed{cs2::LocId(locId), 200}));
        const auto answer = acknowledged<cs2::LocoDirection>(cs2::LocoDirection{cs2::LocId(locId), backward});
        ASSERT_TRUE(answer) << std::hex << locId;
        EXPECT_EQ(answer->direction, backward);
        EXPECT_EQ(loco(locId)->direction, backward);
        EXPECT_EQ(loco(locId)->speed, 0);
    }
}

// 3.6: function F1 on for each.
TEST_P(AcknowledgedCommand, LocoFunctionOfEveryDecoderProtocol) {
    for (std::uint32_t locId : {MfxLoco, Mm2Loco, DccLoco}) {
        const auto answer =
            acknowledged<cs2::LocoFunction>(cs2::LocoFunction{cs2::LocId(locId), 1, 1, std::nullopt});
        ASSERT_TRUE(answer) << std::hex << locId;
        EXPECT_EQ(answer->value, 1);
        ASSERT_NE(loco(locId), nullptr);
        EXPECT_EQ(loco(locId)->functions[1], 1);
    }
}

// 3.7: CV 1 of the DCC loco at address 3 reads 3.
TEST_P(AcknowledgedCommand, ConfigReadOfADccDecoder) {
    const auto answer = acknowledged<cs2::ConfigRead>(
        cs2::ConfigRead{cs2::LocId(DccLoco), cs2::CvAddress{1, 0}, std::uint8_t(1), std::nullopt});
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->value, 3);
}

// 3.8: a CV written on the DCC loco is confirmed and verified, and reads back.
TEST_P(AcknowledgedCommand, ConfigWriteOfADccDecoder) {
    const auto written =
        acknowledged<cs2::ConfigWrite>(cs2::ConfigWrite{cs2::LocId(DccLoco), cs2::CvAddress{3, 0}, 25, 0});
    ASSERT_TRUE(written);
    EXPECT_EQ(written->flags, cs2::ConfigWrite::WriteOk | cs2::ConfigWrite::VerifyOk);
    const auto read = acknowledged<cs2::ConfigRead>(
        cs2::ConfigRead{cs2::LocId(DccLoco), cs2::CvAddress{3, 0}, std::uint8_t(1), std::nullopt});
    ASSERT_TRUE(read);
    EXPECT_EQ(read->value, 25);
}

// 4.1: the first MM turnout thrown to position 0 (round/red), then 1 (straight/green).
TEST_P(AcknowledgedCommand, AccessorySwitch) {
    for (std::uint8_t position : {0, 1}) {
        const auto answer = acknowledged<cs2::AccessorySwitch>(
            cs2::AccessorySwitch{cs2::LocId(FirstTurnout), position, 1, std::nullopt});
        ASSERT_TRUE(answer);
        EXPECT_EQ(answer->position, position);
        EXPECT_EQ(rig_.station.accessoryPosition(FirstTurnout), position);
    }
}

// 2.12: the station's main track current (channel 1) is read.
TEST_P(AcknowledgedCommand, SystemStatusReading) {
    const auto answer =
        acknowledged<cs2::SystemStatus>(cs2::SystemStatus{rig_.station.uid(), 1, std::nullopt, std::nullopt});
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->device, rig_.station.uid());
    EXPECT_TRUE(answer->value.has_value());
}

// 6.1: the station answers a ping with its UID and device type.
TEST_P(AcknowledgedCommand, PingIsAnswered) {
    station::StationUpdates seen;
    QObject::connect(rig_.session.get(), &station::StationSession::updated, rig_.session.get(),
                     [&](const station::StationUpdates& updates) {
                         seen.devices.insert(seen.devices.end(), updates.devices.begin(),
                                             updates.devices.end());
                     });
    rig_.session->ping();
    ASSERT_TRUE(waitFor([&] { return !seen.devices.empty(); }));
    EXPECT_EQ(seen.devices.front().uid, rig_.station.uid());
    const auto* device = rig_.session->devices().find(rig_.station.uid());
    ASSERT_NE(device, nullptr);
    EXPECT_EQ(device->identity.deviceType, seen.devices.front().deviceType);
}

// 6.2: the station's status data: what it is and its measurement channels.
TEST_P(AcknowledgedCommand, StatusDataOfTheStationIsRead) {
    const auto* device = rig_.session->devices().find(rig_.station.uid());
    ASSERT_NE(device, nullptr);
    std::optional<station::DeviceDescription> description;
    QStringList problems;
    rig_.session->statusData().read(device->identity,
                                    [&](const station::DeviceDescription& d, const QStringList& p) {
                                        description = d;
                                        problems = p;
                                    });
    ASSERT_TRUE(waitFor([&] { return description.has_value(); }));
    EXPECT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();
    ASSERT_TRUE(description->summary);
    EXPECT_EQ(description->summary->article, "60215");
    EXPECT_EQ(description->summary->name, "Central Station 2");
    EXPECT_EQ(description->readings.size(), description->summary->readingCount);
    EXPECT_EQ(description->configs.size(), description->summary->configCount);
    EXPECT_GT(description->readings.size(), 0U);
}

INSTANTIATE_TEST_SUITE_P(OverEveryWire, AcknowledgedCommand,
                         ::testing::Values(Wire::Tcp, Wire::Udp, Wire::VirtualCan),
                         [](const ::testing::TestParamInfo<Wire>& info) { return wireName(info.param); });

} // namespace
} // namespace stellwerk::e2e
