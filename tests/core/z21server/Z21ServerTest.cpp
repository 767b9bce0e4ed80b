// Issue 35: the Z21 LAN server over real loopback sockets, in front of a railway on the simulated CS2, with a
// Z21 client of the tests' own: every central request answered, locos driven and confirmed by the station,
// broadcasts of changes from the desk, turnout numbers, bad datagrams counted, silent clients dropped with
// their locos stopped, the station unheard, and one loco driven by two clients.

#include "z21server/Z21Server.h"

#include "ModelBench.h"
#include "Z21TestClient.h"
#include "model/Z21Addresses.h"

namespace stellwerk::z21server::test {
namespace {

using model::test::Br86;
using model::test::ModelBench;
using model::test::V100;
using model::test::waitFor;

constexpr std::uint16_t V100Address = 3;    // DCC: its own address
constexpr std::uint16_t Br86Address = 1000; // mfx: the book's first

z21::LocoSpeed steps128(std::uint8_t step, bool forward = true) {
    return {z21::SpeedStepMode::Steps128, forward, step, false};
}

class Z21ServerTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(bench.start());
        options.address = QHostAddress::LocalHost;
        options.port = 0;
        server = std::make_unique<Z21Server>(addresses, options);
        QObject::connect(server.get(), &Z21Server::event, server.get(),
                         [this](const Z21Event& e) { events.push_back(e); });
        ASSERT_TRUE(server->listen()) << server->errorString().toStdString();
        server->setRailway(&bench.railway);
    }

    std::unique_ptr<Z21TestClient> client(std::uint32_t flags = z21::broadcast::DrivingAndSwitching) {
        auto made = std::make_unique<Z21TestClient>(server->port());
        made->send(z21::SetBroadcastFlags{flags});
        made->send(z21::GetBroadcastFlags{});
        EXPECT_TRUE(made->waitFor<z21::BroadcastFlags>());
        return made;
    }

    int stationSpeed(std::uint32_t loco) const { return bench.station.loco(loco)->speed; }

    bool has(Z21Event::Kind kind) const {
        return std::any_of(events.begin(), events.end(), [&](const Z21Event& e) { return e.kind == kind; });
    }

    ModelBench bench;
    model::Z21Addresses addresses;
    Z21ServerOptions options;
    std::unique_ptr<Z21Server> server;
    std::vector<Z21Event> events;
};

TEST_F(Z21ServerTest, AnswersTheRequestsAboutTheCentral) {
    auto phone = client();
    phone->send(z21::GetSerialNumber{});
    phone->send(z21::GetCode{});
    phone->send(z21::GetHardwareInfo{});
    phone->send(z21::GetXVersion{});
    phone->send(z21::GetFirmwareVersion{});
    phone->send(z21::GetSystemState{});
    phone->send(z21::UnknownRequest{0x99, {1, 2}});
    ASSERT_TRUE(phone->waitFor<z21::UnknownCommand>());
    ASSERT_TRUE(phone->waitFor<z21::SystemState>());
    EXPECT_EQ(phone->last<z21::SerialNumber>()->serial, options.serialNumber);
    EXPECT_EQ(phone->last<z21::FeatureCode>()->code, 0) << "nothing locked, or the app refuses";
    EXPECT_TRUE(phone->last<z21::HardwareInfo>().has_value());
    EXPECT_TRUE(phone->last<z21::XVersion>().has_value());
    EXPECT_TRUE(phone->last<z21::FirmwareVersion>().has_value());
    EXPECT_EQ(phone->last<z21::BroadcastFlags>()->flags, z21::broadcast::DrivingAndSwitching);
    EXPECT_EQ(server->clients().size(), 1U);
    EXPECT_EQ(server->counters().unknown, 1U);
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.front().kind, Z21Event::Kind::Joined);
}

TEST_F(Z21ServerTest, ADriveIsCarriedOutAndTheStationConfirmsTheSpeed) {
    auto phone = client();
    phone->send(z21::SetLocoDrive{V100Address, steps128(63)});
    const int expected = z21::systemSpeed(steps128(63));
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == expected; }));
    ASSERT_TRUE(waitFor([&] {
        const auto info = phone->locoInfo(V100Address);
        return info && info->speed.step == 63;
    }));
    EXPECT_FALSE(phone->locoInfo(V100Address)->busy);
    EXPECT_EQ(bench.railway.throttlePort().owners().driverOf(V100), events.front().client);
}

TEST_F(Z21ServerTest, AnMfxLocoIsDrivenOnTheAddressTheBookGaveIt) {
    EXPECT_EQ(addresses.addressOf(Br86), Br86Address);
    auto phone = client();
    phone->send(z21::SetLocoDrive{Br86Address, {z21::SpeedStepMode::Steps28, true, 14, false}});
    ASSERT_TRUE(waitFor([&] {
        return stationSpeed(Br86) == z21::systemSpeed({z21::SpeedStepMode::Steps28, true, 14, false});
    }));
    phone->send(z21::SetLocoFunction{Br86Address, 1, z21::FunctionAction::Toggle});
    ASSERT_TRUE(waitFor([&] { return bench.station.loco(Br86)->functions[1] != 0; }));
    ASSERT_TRUE(waitFor([&] {
        const auto info = phone->locoInfo(Br86Address);
        return info && (info->functions & 0b10u) && info->speed.mode == z21::SpeedStepMode::Steps28;
    }));
}

TEST_F(Z21ServerTest, TheDesksChangeReachesOnlyTheClientsThatFollowTheLoco) {
    auto follower = client();
    auto other = client();
    follower->send(z21::GetLocoInfo{V100Address});
    ASSERT_TRUE(waitFor([&] { return follower->locoInfo(V100Address).has_value(); }));
    bench.railway.setSpeed(V100, 500);
    ASSERT_TRUE(waitFor([&] {
        const auto info = follower->locoInfo(V100Address);
        return info && info->speed.step == z21::stepForSystemSpeed(z21::SpeedStepMode::Steps128, 500);
    }));
    QTest::qWait(50);
    EXPECT_FALSE(other->locoInfo(V100Address).has_value()) << "it never asked about the loco";
}

TEST_F(Z21ServerTest, Z21TurnoutZeroIsKeyboardNumberOne) {
    auto phone = client();
    phone->send(z21::SetTurnout{0, true, true, false});
    ASSERT_TRUE(waitFor([&] {
        return bench.railway.accessory(1)->isPositionReported() &&
               bench.railway.accessory(1)->position() == 1;
    }));
    phone->send(z21::GetTurnoutInfo{0});
    ASSERT_TRUE(waitFor([&] {
        const auto info = phone->last<z21::TurnoutInfo>();
        return info && info->address == 0 && info->position == z21::TurnoutPosition::Output2;
    }));
    EXPECT_NE(bench.railway.accessory(2)->position(), 1) << "keyboard number 2 is Z21 turnout 1";
}

TEST_F(Z21ServerTest, GarbageAndWrongChecksumsAreCountedAndRequestsStillAnswered) {
    auto phone = client();
    phone->sendBytes({0xDE, 0xAD, 0xBE});             // cut short
    phone->sendBytes({0x02, 0x00, 0x10, 0x00});       // DataLen below four
    phone->sendBytes({0x05, 0x00, 0x10, 0x00, 0x00}); // serial number request one byte too long
    std::vector<std::uint8_t> status = z21::encodeRequest(z21::GetXStatus{});
    status.back() ^= 0xFF; // wrong XOR
    phone->sendBytes(status);
    ASSERT_TRUE(phone->waitFor<z21::XStatusChanged>()) << "answered despite the wrong XOR";
    EXPECT_EQ(server->counters().wrongChecksums, 1U);
    EXPECT_EQ(server->counters().badPackets, 3U);
    phone->send(z21::GetSerialNumber{});
    EXPECT_TRUE(phone->waitFor<z21::SerialNumber>());
}

TEST_F(Z21ServerTest, AClientThatFallsSilentIsDroppedAndItsLocoStopped) {
    options.silence = 300ms;
    server = std::make_unique<Z21Server>(addresses, options);
    QObject::connect(server.get(), &Z21Server::event, server.get(),
                     [this](const Z21Event& e) { events.push_back(e); });
    ASSERT_TRUE(server->listen());
    server->setRailway(&bench.railway);
    auto phone = client();
    phone->send(z21::SetLocoDrive{V100Address, steps128(80)});
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) > 0; }));
    ASSERT_TRUE(waitFor([&] { return server->clients().size() == 0; }));
    EXPECT_TRUE(has(Z21Event::Kind::TimedOut));
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == 0; })) << "its loco is stopped";
}

TEST_F(Z21ServerTest, ALogoffStopsTheClientsLocos) {
    auto phone = client();
    phone->send(z21::SetLocoDrive{V100Address, steps128(80)});
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) > 0; }));
    phone->send(z21::Logoff{});
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == 0; }));
    EXPECT_EQ(server->clients().size(), 0U);
    EXPECT_TRUE(has(Z21Event::Kind::LoggedOff));
}

TEST_F(Z21ServerTest, AClientDroppedByTheOperatorIsForgottenAndItsLocoStopped) {
    auto phone = client();
    phone->send(z21::SetLocoDrive{V100Address, steps128(80)});
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) > 0; }));
    ASSERT_EQ(server->clients().size(), 1U);
    const Z21Client& known = server->clients().all().begin()->second;
    EXPECT_EQ(known.lastRequest, QStringLiteral("LAN_X_SET_LOCO_DRIVE 3"));
    EXPECT_TRUE(known.lastRequestAt.isValid());
    const QString name = known.name();
    EXPECT_FALSE(server->dropClient(QStringLiteral("z21 127.0.0.1:1"))) << "nobody by that name";
    EXPECT_TRUE(server->dropClient(name));
    EXPECT_EQ(server->clients().size(), 0U);
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == 0; }));
    EXPECT_TRUE(has(Z21Event::Kind::Dropped));
    EXPECT_TRUE(bench.railway.throttlePort().owners().drivenBy(name).isEmpty());
}

TEST_F(Z21ServerTest, WhileTheStationIsNotHeardADriveIsRefusedToldAndNeverReplayed) {
    auto phone = client();
    bench.stall();
    bench.stationEnd.close();
    ASSERT_FALSE(bench.railway.isStateReported());
    ASSERT_TRUE(phone->waitFor<z21::TrackPowerOff>()) << "clients are told the power is off";
    const std::size_t toldBefore = phone->all<z21::TrackPowerOff>().size();
    phone->send(z21::SetLocoDrive{V100Address, steps128(90)});
    ASSERT_TRUE(waitFor([&] { return server->counters().refused == 1; }));
    ASSERT_TRUE(waitFor([&] { return phone->all<z21::TrackPowerOff>().size() > toldBefore; }))
        << "told again";
    EXPECT_TRUE(has(Z21Event::Kind::Refused));
    bench.stationEnd.open();
    bench.wake();
    QTest::qWait(200);
    EXPECT_EQ(stationSpeed(V100), 0) << "nothing refused is sent later";
}

TEST_F(Z21ServerTest, TheLastClientToDriveTakesTheLocoAndTheFirstIsTold) {
    auto first = client();
    auto second = client();
    first->send(z21::SetLocoDrive{V100Address, steps128(40)});
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == z21::systemSpeed(steps128(40)); }));
    second->send(z21::SetLocoDrive{V100Address, steps128(100)});
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == z21::systemSpeed(steps128(100)); }));
    ASSERT_TRUE(waitFor([&] {
        const auto info = first->locoInfo(V100Address);
        return info && info->busy;
    })) << "the first is told another drives it";
    EXPECT_TRUE(has(Z21Event::Kind::TakenOver));
    const auto mine = second->locoInfo(V100Address);
    ASSERT_TRUE(mine.has_value());
    EXPECT_FALSE(mine->busy);
}

TEST_F(Z21ServerTest, AFloodingClientIsLimitedAndAnotherIsStillServed) {
    options.datagramsPerSecond = 50;
    server = std::make_unique<Z21Server>(addresses, options);
    ASSERT_TRUE(server->listen());
    server->setRailway(&bench.railway);
    auto calm = client();
    Z21TestClient flood(server->port());
    for (int burst = 0; burst < 20;
         ++burst) { // 1,000 datagrams in about a second, a request of calm's in each
        for (int i = 0; i < 50; ++i)
            flood.send(z21::GetSerialNumber{});
        calm->send(z21::GetSerialNumber{});
        QTest::qWait(10);
    }
    ASSERT_TRUE(waitFor([&] { return calm->all<z21::SerialNumber>().size() == 20; }))
        << "every one of the calm client's requests answered";
    EXPECT_GT(server->counters().limited, 0U);
    EXPECT_LE(flood.all<z21::SerialNumber>().size(), 100U) << "at most a window or two of answers";
}

TEST_F(Z21ServerTest, DatagramsFromAnAddressNotAllowedAreIgnored) {
    options.allowedClients = {QHostAddress(QStringLiteral("127.0.0.2"))};
    server = std::make_unique<Z21Server>(addresses, options);
    ASSERT_TRUE(server->listen());
    server->setRailway(&bench.railway);
    Z21TestClient stranger(server->port()); // sends from 127.0.0.1
    stranger.send(z21::GetSerialNumber{});
    ASSERT_TRUE(waitFor([&] { return server->counters().notAllowed == 1; }));
    EXPECT_FALSE(stranger.waitFor<z21::SerialNumber>(200)) << "no answer to a stranger";
    EXPECT_EQ(server->clients().size(), 0U);

    options.allowedClients = {QHostAddress(QStringLiteral("127.0.0.2")), QHostAddress::LocalHost};
    server = std::make_unique<Z21Server>(addresses, options);
    ASSERT_TRUE(server->listen());
    Z21TestClient allowed(server->port());
    allowed.send(z21::GetSerialNumber{});
    EXPECT_TRUE(allowed.waitFor<z21::SerialNumber>());
    EXPECT_EQ(server->counters().notAllowed, 0U);
    EXPECT_EQ(server->clients().size(), 1U);
}

} // namespace
} // namespace stellwerk::z21server::test
