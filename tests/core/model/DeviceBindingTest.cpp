// Devices as part of the railway (issue 15): accessories bound to an RO relay or an OpenRailCAN decoder
// output are switched there, not at the CS2, and reported only when the device confirmed them; contacts
// bound to device inputs are lit by them; routes switch bound and station accessories alike. The real
// sessions drive simulated devices over a loopback transport.

#include "DeviceBench.h"
#include "cs2/Codec.h"

#include <QSettings>
#include <QTemporaryDir>

namespace stellwerk::model::test {
namespace {

// The accessory switchings the station received (on-commands), by wire address.
struct StationSwitches {
    explicit StationSwitches(ModelBench& bench) {
        QObject::connect(&bench.stationEnd, &transport::Transport::framesReceived, &context,
                         [this](const std::vector<can::CanFrame>& frames) {
                             for (const auto& frame : frames) {
                                 const auto message = cs2::decode(frame);
                                 const auto* sw =
                                     message ? std::get_if<cs2::AccessorySwitch>(&message->body) : nullptr;
                                 if (sw && !message->response && sw->current != 0)
                                     addresses.push_back(sw->article.value());
                             }
                         });
    }
    QObject context;
    std::vector<std::uint32_t> addresses;
};

class DeviceBinding : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(bench.start()); }
    Railway& railway() { return bench.railway.railway; }
    bool reportedAt(std::int64_t id, int position) {
        const Accessory* accessory = railway().accessory(id);
        return accessory && accessory->isPositionReported() && accessory->position() == position;
    }

    DeviceBench bench;
};

TEST_F(DeviceBinding, AnAccessoryBoundToARelayIsSwitchedByTheModuleNotTheStation) {
    StationSwitches station(bench.railway);
    QSignalSpy ended(&railway(), &Railway::switchingEnded);
    railway().switchAccessory(1, 1);
    EXPECT_FALSE(reportedAt(1, 1)) << "reported before the module said OK";
    ASSERT_TRUE(waitFor([&] { return ended.count() == 1; }));
    EXPECT_TRUE(ended.at(0).at(2).toBool());
    EXPECT_TRUE(bench.module.relay(1));
    EXPECT_TRUE(reportedAt(1, 1));
    railway().switchAccessory(1, 0);
    ASSERT_TRUE(waitFor([&] { return ended.count() == 2; }));
    EXPECT_FALSE(bench.module.relay(1));
    EXPECT_TRUE(reportedAt(1, 0));
    QTest::qWait(100);
    EXPECT_TRUE(station.addresses.empty()) << "the CS2 was asked to switch a device's accessory";
}

TEST_F(DeviceBinding, AnAccessoryBoundToADecoderOutputSetsOnlyItsBitAndIsReportedOnTheAck) {
    StationSwitches station(bench.railway);
    QSignalSpy ended(&railway(), &Railway::switchingEnded);
    railway().switchAccessory(5, 1);
    ASSERT_TRUE(waitFor([&] { return ended.count() == 1; }));
    EXPECT_TRUE(ended.at(0).at(2).toBool());
    EXPECT_EQ(bench.decoder.outputs(), 0x04) << "output 2 is bit 2 of Pos";
    EXPECT_TRUE(reportedAt(5, 1));
    railway().switchAccessory(5, 0);
    ASSERT_TRUE(waitFor([&] { return ended.count() == 2; }));
    EXPECT_EQ(bench.decoder.outputs(), 0x00);
    EXPECT_TRUE(reportedAt(5, 0));
    EXPECT_TRUE(station.addresses.empty());
}

// Route 1 of the bench: W1 straight (the relay), S5 green (the decoder), W2 third position (the CS2).
TEST_F(DeviceBinding, ARouteSwitchesRelaysDecoderOutputsAndStationArticlesInItsOrder) {
    StationSwitches station(bench.railway);
    QSignalSpy finished(&railway(), &Railway::routeFinished);
    QSignalSpy failed(&railway(), &Railway::routeFailed);
    ASSERT_TRUE(railway().runRoute(1));
    ASSERT_TRUE(waitFor([&] { return finished.count() + failed.count() == 1; }));
    ASSERT_EQ(finished.count(), 1) << failed.at(0).at(1).toString().toStdString();
    EXPECT_TRUE(bench.module.relay(1));
    EXPECT_EQ(bench.decoder.outputs(), 0x04);
    EXPECT_EQ(station.addresses, std::vector<std::uint32_t>{0x3002u}) << "only W2 went to the CS2";
    EXPECT_TRUE(railway().isRouteSet(1));
}

TEST_F(DeviceBinding, ContactsAreLitByTheEncoderAndTheModulesInputs) {
    QSignalSpy contacts(&railway(), &Railway::contactsChanged);
    bench.encoder.setInput(3, true);
    ASSERT_TRUE(waitFor([&] {
        const FeedbackContact* contact = railway().contact(EncoderContact);
        return contact && contact->known() && contact->occupied();
    }));
    bench.module.setInput(2, true);
    ASSERT_TRUE(waitFor([&] { return railway().contact(ModuleContact)->occupied(); }));
    bench.encoder.setInput(3, false);
    ASSERT_TRUE(waitFor([&] { return !railway().contact(EncoderContact)->occupied(); }));
    EXPECT_TRUE(railway().contact(EncoderContact)->known());
    bench.encoder.setInput(4, true); // not bound
    QTest::qWait(100);
    EXPECT_FALSE(railway().contact(EncoderContact)->occupied());
    EXPECT_FALSE(contacts.isEmpty());
}

// Nothing reported switched that was not: a module that stops answering makes its relays "not reported"
// and refuses switchings; when it answers again its relays are read and reported anew.
TEST_F(DeviceBinding, AnOfflineModulesAccessoryIsNotReportedAndCannotBeSwitched) {
    QSignalSpy ended(&railway(), &Railway::switchingEnded);
    QSignalSpy problems(&railway(), &Railway::problem);
    railway().switchAccessory(1, 1);
    ASSERT_TRUE(waitFor([&] { return reportedAt(1, 1); }));
    bench.module.unplug();
    ASSERT_TRUE(waitFor([&] { return !railway().accessory(1)->isPositionReported(); }));
    EXPECT_FALSE(railway().contact(ModuleContact)->known());
    railway().switchAccessory(1, 0);
    ASSERT_TRUE(waitFor([&] { return ended.count() == 2; }));
    EXPECT_FALSE(ended.at(1).at(2).toBool());
    EXPECT_TRUE(bench.module.relay(1)) << "an offline module was switched";
    ASSERT_FALSE(problems.isEmpty());
    EXPECT_TRUE(problems.last().at(0).toString().contains(QStringLiteral("offline")))
        << problems.last().at(0).toString().toStdString();
    bench.module.plugIn();
    ASSERT_TRUE(waitFor([&] { return reportedAt(1, 1); }));
}

TEST_F(DeviceBinding, AnOfflineDecodersAccessoryIsNotReported) {
    railway().switchAccessory(5, 1);
    ASSERT_TRUE(waitFor([&] { return reportedAt(5, 1); }));
    bench.decoder.unplug();
    ASSERT_TRUE(waitFor([&] { return !railway().accessory(5)->isPositionReported(); }));
    QSignalSpy ended(&railway(), &Railway::switchingEnded);
    railway().switchAccessory(5, 0);
    ASSERT_TRUE(waitFor([&] { return ended.count() == 1; }));
    EXPECT_FALSE(ended.at(0).at(2).toBool());
    EXPECT_EQ(bench.decoder.outputs(), 0x04);
}

// Like a CS2 article before the station reported it: the decoder has not confirmed any Pos yet.
TEST_F(DeviceBinding, ADecoderOutputIsNotReportedBeforeItsFirstConfirmedSwitch) {
    QTest::qWait(300); // pings and their answers pass
    EXPECT_FALSE(railway().accessory(5)->isPositionReported());
}

// A decoder powered up again may have lost its outputs: back online, it is "not reported" until it
// confirms a switching again.
TEST_F(DeviceBinding, ADecoderThatCameBackIsNotReportedUntilItConfirmsASwitchAgain) {
    railway().switchAccessory(5, 1);
    ASSERT_TRUE(waitFor([&] { return reportedAt(5, 1); }));
    bench.decoder.unplug();
    ASSERT_TRUE(waitFor([&] { return !railway().accessory(5)->isPositionReported(); }));
    bench.decoder.plugIn();
    ASSERT_TRUE(waitFor(
        [&] { return bench.orc->device(DecoderUid)->state == orccentral::OrcDevice::State::Online; }));
    QTest::qWait(300); // a few pings answered
    EXPECT_FALSE(railway().accessory(5)->isPositionReported()) << "claimed what it confirmed before";
    railway().switchAccessory(5, 1);
    ASSERT_TRUE(waitFor([&] { return reportedAt(5, 1); }));
}

TEST_F(DeviceBinding, SessionsThatAreGoneLeaveEveryBoundItemNotReported) {
    railway().switchAccessory(1, 1);
    bench.encoder.setInput(3, true);
    ASSERT_TRUE(waitFor([&] { return reportedAt(1, 1) && railway().contact(EncoderContact)->occupied(); }));
    bench.devices.setSessions(nullptr, {});
    EXPECT_FALSE(railway().accessory(1)->isPositionReported());
    EXPECT_FALSE(railway().contact(EncoderContact)->known());
    QSignalSpy ended(&railway(), &Railway::switchingEnded);
    railway().switchAccessory(1, 0);
    ASSERT_EQ(ended.count(), 1);
    EXPECT_FALSE(ended.at(0).at(2).toBool());

    bench.devices.setSessions(bench.orc.get(), {bench.roModule.get()});
    EXPECT_TRUE(reportedAt(1, 1)) << "the sessions still know the relays";
}

// A switching waits for its own session only: the module's session going fails the relay's switching, the
// decoder's switching on the central that stays goes on to its acknowledgement.
TEST_F(DeviceBinding, ASwitchingFailsWhenItsSessionGoesAndOnlyThen) {
    QSignalSpy ended(&railway(), &Railway::switchingEnded);
    railway().switchAccessory(1, 1);
    railway().switchAccessory(5, 1);
    ASSERT_EQ(ended.count(), 0);
    bench.devices.setSessions(bench.orc.get(), {});
    ASSERT_EQ(ended.count(), 1);
    EXPECT_EQ(ended.at(0).at(0).toLongLong(), 1);
    EXPECT_FALSE(ended.at(0).at(2).toBool());
    ASSERT_TRUE(waitFor([&] { return ended.count() == 2; }));
    EXPECT_EQ(ended.at(1).at(0).toLongLong(), 5);
    EXPECT_TRUE(ended.at(1).at(2).toBool());
    EXPECT_TRUE(reportedAt(5, 1));
}

TEST(DeviceBindingUnconfirmed, ADecoderThatDoesNotAcknowledgeLeavesThePositionNotReported) {
    DeviceBench bench(false);
    ASSERT_TRUE(bench.start());
    Railway& railway = bench.railway.railway;
    QSignalSpy ended(&railway, &Railway::switchingEnded);
    railway.switchAccessory(5, 1);
    ASSERT_TRUE(waitFor([&] { return ended.count() == 1; }));
    EXPECT_FALSE(ended.at(0).at(2).toBool());
    EXPECT_EQ(bench.decoder.outputs(), 0x04) << "the decoder did switch";
    EXPECT_FALSE(railway.accessory(5)->isPositionReported());
}

// A decoder that confirmed a Pos and then leaves a switching unconfirmed may be in either: not reported.
TEST(DeviceBindingUnconfirmed, AnUnconfirmedSwitchingForgetsTheConfirmedPosition) {
    DeviceBench bench;
    ASSERT_TRUE(bench.start());
    Railway& railway = bench.railway.railway;
    QSignalSpy ended(&railway, &Railway::switchingEnded);
    railway.switchAccessory(5, 1);
    ASSERT_TRUE(waitFor([&] { return ended.count() == 1; }));
    ASSERT_TRUE(railway.accessory(5)->isPositionReported());
    bench.simulatedBus.detach(bench.decoder); // it hears nothing more, and answers no ping
    railway.switchAccessory(5, 0);
    ASSERT_TRUE(waitFor([&] { return ended.count() == 2; }));
    EXPECT_FALSE(ended.at(1).at(2).toBool());
    EXPECT_FALSE(railway.accessory(5)->isPositionReported());
}

TEST(DeviceBindings, AreSavedAndReadBack) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QSettings file(dir.filePath(QStringLiteral("stellwerk.ini")), QSettings::IniFormat);
    DeviceBindings saved = benchBindings();
    saved.accessories.push_back({9, OrcOutput{0x3005, std::nullopt}});
    saved.save(file);
    file.sync();
    QSettings again(file.fileName(), QSettings::IniFormat);
    const DeviceBindings read = DeviceBindings::load(again);
    EXPECT_EQ(read.accessories, saved.accessories);
    EXPECT_EQ(read.contacts, saved.contacts);
    ASSERT_NE(read.accessory(9), nullptr);
    EXPECT_EQ(std::get<OrcOutput>(read.accessory(9)->output).target, 0x3005);
    EXPECT_EQ(read.contact(contactKey(0, 99)), nullptr);
}

} // namespace
} // namespace stellwerk::model::test
