// The station address as the Connect dialog shows it: read into parts and built back, from the connection
// layer (the dialog never sees a transport).

#include "connection/StationAddress.h"

#include <QCanBus>
#include <gtest/gtest.h>

namespace stellwerk::connection::test {
namespace {

using Kind = StationEndpoint::Kind;

TEST(StationAddress, ReadsTheKindAndTheHostOrInterface) {
    const auto udp = StationAddress::read(QStringLiteral(" udp://192.168.2.5 "));
    ASSERT_TRUE(udp.hasValue()) << udp.error().toStdString();
    EXPECT_EQ(udp->kind, Kind::Udp);
    EXPECT_EQ(udp->host, QStringLiteral("192.168.2.5"));
    const auto tcp = StationAddress::read(QStringLiteral("tcp://cs2.local:15732"));
    ASSERT_TRUE(tcp.hasValue());
    EXPECT_EQ(tcp->kind, Kind::Tcp);
    EXPECT_EQ(tcp->host, QStringLiteral("cs2.local"));
    const auto can = StationAddress::read(QStringLiteral("can://socketcan/can0"));
    ASSERT_TRUE(can.hasValue());
    EXPECT_EQ(can->kind, Kind::CanBus);
    EXPECT_EQ(can->canInterface, QStringLiteral("socketcan/can0"));
}

TEST(StationAddress, AnUnusableAddressSaysWhy) {
    const auto bad = StationAddress::read(QStringLiteral("ftp://x"));
    ASSERT_FALSE(bad.hasValue());
    EXPECT_FALSE(bad.error().isEmpty());
    EXPECT_EQ(StationAddress::endpointOf(QStringLiteral("ftp://x")).kind, Kind::Unusable);
    EXPECT_EQ(StationAddress::endpointOf(QString()), StationEndpoint::simulated());
    EXPECT_EQ(StationAddress::endpointOf(QStringLiteral("tcp://10.0.0.2")).description(),
              QStringLiteral("CS2 at 10.0.0.2 (TCP)"));
}

TEST(StationAddress, ANewHostKeepsThePortsOfTheSameKind) {
    EXPECT_EQ(
        StationAddress::atHost(Kind::Tcp, QStringLiteral("10.0.0.9"), QStringLiteral("tcp://cs2:15799")),
        QStringLiteral("tcp://10.0.0.9:15799"));
    EXPECT_EQ(
        StationAddress::atHost(Kind::Udp, QStringLiteral("10.0.0.9"), QStringLiteral("tcp://cs2:15799")),
        QStringLiteral("udp://10.0.0.9:15731"));
    EXPECT_EQ(StationAddress::atHost(Kind::Udp, QString(), QStringLiteral("udp://cs2")),
              QStringLiteral("udp://"));
    EXPECT_EQ(StationAddress::ofCanInterface(QStringLiteral(" virtualcan/can0 ")),
              QStringLiteral("can://virtualcan/can0"));
}

TEST(StationAddress, CanInterfacesAreNamedPluginSlashInterface) {
    const std::vector<CanInterfaceChoice> choices = availableCanInterfaces();
    const bool virtualCan = QCanBus::instance()->plugins().contains(QStringLiteral("virtualcan"));
    if (virtualCan) {
        ASSERT_FALSE(choices.empty());
    }
    for (const CanInterfaceChoice& choice : choices) {
        EXPECT_TRUE(choice.name.contains(QLatin1Char('/'))) << choice.name.toStdString();
        EXPECT_TRUE(StationAddress::read(StationAddress::ofCanInterface(choice.name)).hasValue())
            << choice.name.toStdString();
    }
}

} // namespace
} // namespace stellwerk::connection::test
