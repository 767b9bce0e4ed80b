// The server's book of clients and the Z21 address book: subscriptions kept to the spec's sixteen, silent
// clients found, the flood limit per client; DCC locos keep their address, MM and mfx get one that never
// collides, kept in the settings.

#include "z21server/Z21Clients.h"

#include "model/Z21Addresses.h"

#include <QSettings>
#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <set>

namespace stellwerk::z21server::test {
namespace {

constexpr std::uint32_t Mm24 = 0x0018; // MM address 24
constexpr std::uint32_t Mm3 = 0x0003;  // MM address 3
constexpr std::uint32_t Dcc3 = 0xC003; // DCC address 3
constexpr std::uint32_t Mfx6 = 0x4006;
constexpr std::uint32_t Mfx7 = 0x4007;

TEST(Z21ClientsTest, AClientFollowsAtMostSixteenLocosTheOldestForgottenFirst) {
    Z21Client client;
    for (std::uint16_t address = 1; address <= 17; ++address)
        client.subscribe(address, z21::SpeedStepMode::Steps128);
    EXPECT_EQ(client.subscriptions.size(), Z21Client::MaxSubscriptions);
    EXPECT_FALSE(client.follows(1));
    EXPECT_TRUE(client.follows(17));
    client.subscribe(2, z21::SpeedStepMode::Steps28);
    EXPECT_EQ(client.subscription(2)->mode, z21::SpeedStepMode::Steps28);
}

TEST(Z21ClientsTest, SilentClientsAreTakenOutAndTheFloodLimitIsPerClient) {
    Z21Clients clients;
    clients.heard(QHostAddress::LocalHost, 1000, 0);
    Z21Client& busy = clients.heard(QHostAddress::LocalHost, 1001, 0);
    clients.heard(QHostAddress::LocalHost, 1001, 50'000);
    const auto dropped = clients.dropSilent(60'000, 60'000);
    ASSERT_EQ(dropped.size(), 1U);
    EXPECT_EQ(dropped.front().port, 1000);
    EXPECT_EQ(clients.size(), 1U);
    int admitted = 0;
    for (int i = 0; i < 30; ++i)
        admitted += Z21Clients::admit(busy, 50'000, 10) ? 1 : 0;
    EXPECT_EQ(admitted, 10);
    EXPECT_EQ(busy.limited, 20U);
    EXPECT_TRUE(Z21Clients::admit(busy, 51'000, 10)) << "a new second";
}

TEST(Z21AddressesTest, DccKeepsItsAddressMmAndMfxGetOnesThatNeverCollide) {
    model::Z21Addresses book;
    const std::vector<std::uint32_t> locos{Dcc3, Mm3, Mm24, Mfx6, Mfx7};
    book.cover(locos);
    EXPECT_EQ(book.addressOf(Dcc3), 3);
    EXPECT_EQ(book.addressOf(Mm24), 24) << "an MM loco keeps its MM address while it is free";
    EXPECT_NE(book.addressOf(Mm3), 3) << "DCC 3 has it";
    std::set<std::uint16_t> seen;
    for (const std::uint32_t loco : locos)
        seen.insert(*book.addressOf(loco));
    EXPECT_EQ(seen.size(), locos.size());
    EXPECT_EQ(book.locoAt(24, locos), Mm24);
    EXPECT_EQ(book.assign(Mfx6, 3, locos), model::Z21Addresses::Refusal::Taken);
    EXPECT_EQ(book.assign(Mfx6, 24, locos), model::Z21Addresses::Refusal::Taken);
    EXPECT_EQ(book.assign(Dcc3, 50, locos), model::Z21Addresses::Refusal::DccKeepsItsAddress);
    EXPECT_EQ(book.assign(Mfx6, 0, locos), model::Z21Addresses::Refusal::OutOfRange);
    EXPECT_EQ(book.assign(Mfx6, 86, locos), model::Z21Addresses::Refusal::None);
    EXPECT_EQ(book.addressOf(Mfx6), 86);
}

TEST(Z21AddressesTest, TheBookIsKeptInTheSettings) {
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    model::Z21Addresses book;
    book.cover({Mfx6, Mm24});
    ASSERT_EQ(book.assign(Mfx6, 86, {Mfx6, Mm24}), model::Z21Addresses::Refusal::None);
    book.save(settings);
    const model::Z21Addresses loaded = model::Z21Addresses::load(settings);
    EXPECT_EQ(loaded.addressOf(Mfx6), 86);
    EXPECT_EQ(loaded.addressOf(Mm24), 24);
    EXPECT_EQ(loaded.entries(), book.entries());
}

} // namespace
} // namespace stellwerk::z21server::test
