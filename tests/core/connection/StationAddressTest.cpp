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

// Issue 32: where the station's web server is, for a station that does not serve on port 80.
TEST(StationAddress, AnHttpOptionNamesTheWebServerPort) {
    const auto tcp = StationAddress::read(QStringLiteral("tcp://127.0.0.1:15731?http=8080"));
    ASSERT_TRUE(tcp.hasValue()) << tcp.error().toStdString();
    EXPECT_EQ(tcp->kind, Kind::Tcp);
    EXPECT_EQ(tcp->host, QStringLiteral("127.0.0.1"));
    EXPECT_EQ(tcp->webPort, std::optional<std::uint16_t>(8080));
    EXPECT_EQ(StationAddress::split(QStringLiteral("tcp://127.0.0.1:15731?http=8080"))->transport,
              QStringLiteral("tcp://127.0.0.1:15731"));
    const auto udp = StationAddress::split(QStringLiteral("udp://cs2?listen=0&http=8080"));
    EXPECT_EQ(udp->transport, QStringLiteral("udp://cs2?listen=0"));
    EXPECT_EQ(udp->webPort, std::optional<std::uint16_t>(8080));
    EXPECT_EQ(StationAddress::split(QStringLiteral(" can://virtualcan/can0 "))->transport,
              QStringLiteral("can://virtualcan/can0"));
    EXPECT_EQ(StationAddress::endpointOf(QStringLiteral("tcp://127.0.0.1:15731?http=8080")).description(),
              QStringLiteral("CS2 at 127.0.0.1 (TCP)"));
}

TEST(StationAddress, TheWebServerIsOnPort80UnlessTheAddressSaysOtherwise) {
    EXPECT_EQ(StationAddress::webServerOf(QStringLiteral("udp://192.168.2.5")),
              QStringLiteral("http://192.168.2.5"));
    EXPECT_EQ(StationAddress::webServerOf(QStringLiteral("tcp://127.0.0.1:15731?http=8080")),
              QStringLiteral("http://127.0.0.1:8080"));
    EXPECT_EQ(StationAddress::webServerOf(QStringLiteral("udp://cs2?listen=0&http=80")),
              QStringLiteral("http://cs2"));
    EXPECT_EQ(StationAddress::webServerOf(QStringLiteral("can://virtualcan/can0")), QString());
    EXPECT_EQ(StationAddress::webServerOf(QStringLiteral("tcp://cs2?http=x")), QString());
}

TEST(StationAddress, AnHttpOptionThatIsNoPortOrOnACanInterfaceIsRefused) {
    const auto notANumber = StationAddress::read(QStringLiteral("tcp://cs2?http=web"));
    ASSERT_FALSE(notANumber.hasValue());
    EXPECT_EQ(notANumber.error(), QStringLiteral("web server port 'web' is not a number from 1 to 65535"));
    EXPECT_FALSE(StationAddress::read(QStringLiteral("tcp://cs2?http=0")).hasValue());
    EXPECT_FALSE(StationAddress::read(QStringLiteral("tcp://cs2?http=70000")).hasValue());
    const auto can = StationAddress::read(QStringLiteral("can://virtualcan/can0?http=8080"));
    ASSERT_FALSE(can.hasValue());
    EXPECT_EQ(can.error(),
              QStringLiteral("a CAN interface has no web server ('http' is for UDP and TCP stations)"));
    EXPECT_EQ(StationAddress::endpointOf(QStringLiteral("tcp://cs2?http=web")).kind, Kind::Unusable);
}

TEST(StationAddress, ANewHostKeepsTheWebServerPort) {
    EXPECT_EQ(StationAddress::atHost(Kind::Tcp, QStringLiteral("10.0.0.9"),
                                     QStringLiteral("tcp://127.0.0.1:15799?http=8080")),
              QStringLiteral("tcp://10.0.0.9:15799?http=8080"));
    EXPECT_EQ(StationAddress::atHost(Kind::Udp, QStringLiteral("10.0.0.9"),
                                     QStringLiteral("udp://127.0.0.1?listen=0&http=8080")),
              QStringLiteral("udp://10.0.0.9:15731?listen=0&http=8080"));
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
