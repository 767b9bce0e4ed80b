#include "connection/StationEndpoint.h"

#include "transport/TransportAddress.h"

#include <gtest/gtest.h>

using namespace stellwerk;
using connection::StationEndpoint;

namespace {

StationEndpoint endpointOf(const char* url) {
    const auto settings = transport::parseTransportUrl(QString::fromLatin1(url));
    EXPECT_TRUE(settings.hasValue()) << url;
    return StationEndpoint::of(settings.value());
}

} // namespace

TEST(StationEndpoint, SimulatedIsTheDemoLayout) {
    EXPECT_EQ(StationEndpoint::simulated().description(), QStringLiteral("Simulated CS2 (demo layout)"));
}

TEST(StationEndpoint, UdpGatewayByItsAddress) {
    const StationEndpoint endpoint = endpointOf("udp://192.168.2.5");
    EXPECT_EQ(endpoint.kind, StationEndpoint::Kind::Udp);
    EXPECT_EQ(endpoint.description(), QStringLiteral("CS2 at 192.168.2.5 (UDP)"));
}

TEST(StationEndpoint, TcpShowsAPortOtherThan15731) {
    EXPECT_EQ(endpointOf("tcp://192.168.2.5").description(), QStringLiteral("CS2 at 192.168.2.5 (TCP)"));
    EXPECT_EQ(endpointOf("tcp://192.168.2.5:15732").description(),
              QStringLiteral("CS2 at 192.168.2.5:15732 (TCP)"));
}

TEST(StationEndpoint, CanInterfaceByPluginAndName) {
    const StationEndpoint endpoint = endpointOf("can://socketcan/can0");
    EXPECT_EQ(endpoint.kind, StationEndpoint::Kind::CanBus);
    EXPECT_EQ(endpoint.description(), QStringLiteral("CAN interface socketcan/can0"));
}

TEST(StationEndpoint, UnusableAddressIsQuotedAsTyped) {
    EXPECT_EQ(StationEndpoint::unusable(QStringLiteral("http://cs2")).description(),
              QStringLiteral("Station \"http://cs2\""));
}
