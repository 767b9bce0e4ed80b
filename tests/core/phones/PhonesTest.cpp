// Issue 35: where a phone server listens, read alike by `stellwerk --z21` and `stellwerk-cli serve --z21`,
// and the phone settings kept in the group "phones" (both servers off by default).

#include "phones/ListenAddress.h"
#include "phones/PhoneSettings.h"

#include <QSettings>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace stellwerk::phones::test {
namespace {

TEST(ListenAddress, APortAloneListensOnEveryInterface) {
    const auto read = ListenAddress::parse(QStringLiteral("21106"), 21105);
    ASSERT_TRUE(read);
    EXPECT_EQ(read->address, QHostAddress(QHostAddress::Any));
    EXPECT_EQ(read->port, 21106);
    EXPECT_EQ(read->text(), QStringLiteral("21106"));
}

TEST(ListenAddress, HostAndPortListenOnOneAddress) {
    const auto read = ListenAddress::parse(QStringLiteral("192.168.1.20:12091"), 12090);
    ASSERT_TRUE(read);
    EXPECT_EQ(read->address, QHostAddress(QStringLiteral("192.168.1.20")));
    EXPECT_EQ(read->port, 12091);
    EXPECT_EQ(ListenAddress::parse(read->text(), 1), read) << "text() is read back the same";
}

TEST(ListenAddress, NothingGivenIsTheDefaultPort) {
    const auto read = ListenAddress::parse(QString(), 21105);
    ASSERT_TRUE(read);
    EXPECT_EQ(read->port, 21105);
}

TEST(ListenAddress, GarbageIsRefused) {
    EXPECT_FALSE(ListenAddress::parse(QStringLiteral("abc"), 21105));
    EXPECT_FALSE(ListenAddress::parse(QStringLiteral("70000"), 21105));
    EXPECT_FALSE(ListenAddress::parse(QStringLiteral("no.such.host:21105"), 21105));
    EXPECT_FALSE(ListenAddress::parse(QStringLiteral("127.0.0.1:port"), 21105));
}

TEST(PhoneSettings, BothServersAreOffUntilSwitchedOnAndAreKept) {
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    PhoneSettings loaded = PhoneSettings::load(settings);
    EXPECT_FALSE(loaded.z21);
    EXPECT_FALSE(loaded.withrottle);
    EXPECT_EQ(loaded.z21Listen.port, PhoneSettings::Z21Port);
    EXPECT_EQ(loaded.withrottleListen.port, PhoneSettings::WiThrottlePort);

    loaded.z21 = true;
    loaded.z21Listen = {QHostAddress(QStringLiteral("10.0.0.2")), 21200};
    loaded.allowedClients = *PhoneSettings::parseClients(QStringLiteral("10.0.0.5, 10.0.0.6"));
    loaded.save(settings);
    EXPECT_EQ(settings.value(QStringLiteral("phones/z21Listen")).toString(),
              QStringLiteral("10.0.0.2:21200"));
    EXPECT_EQ(PhoneSettings::load(settings), loaded);
}

TEST(PhoneSettings, ClientListsAreAddressesOnly) {
    EXPECT_EQ(PhoneSettings::parseClients(QStringLiteral(""))->size(), 0);
    EXPECT_EQ(PhoneSettings::parseClients(QStringLiteral("10.0.0.5;10.0.0.6 ::1"))->size(), 3);
    EXPECT_FALSE(PhoneSettings::parseClients(QStringLiteral("10.0.0.5, phone")));
}

} // namespace
} // namespace stellwerk::phones::test
