// Transport addresses: udp://host[:port][?listen=port], tcp://host[:port],
// can://plugin/interface[?bitrate=n], and the transports the factory makes from them.

#include "transport/TransportAddress.h"

#include "TestSupport.h"
#include "transport/CanBusTransport.h"
#include "transport/TcpTransport.h"
#include "transport/TransportFactory.h"
#include "transport/UdpTransport.h"

namespace stellwerk::transport::test {
namespace {

template <class T>
T parsedAs(const QString& text) {
    const auto result = parseTransportUrl(text);
    EXPECT_TRUE(result.hasValue()) << text.toStdString() << ": "
                                   << (result ? "" : result.error().toStdString());
    if (!result)
        return T{};
    const T* settings = std::get_if<T>(&*result);
    EXPECT_NE(settings, nullptr) << text.toStdString();
    return settings ? *settings : T{};
}

QString errorOf(const QString& text) {
    const auto result = parseTransportUrl(text);
    EXPECT_FALSE(result.hasValue()) << text.toStdString() << " was accepted";
    return result ? QString() : result.error();
}

TEST(TransportAddress, UdpUsesTheStationPortsByDefault) {
    const auto udp = parsedAs<UdpSettings>(QStringLiteral("udp://192.168.1.2"));
    EXPECT_EQ(udp.host, QStringLiteral("192.168.1.2"));
    EXPECT_EQ(udp.remotePort, 15731);
    EXPECT_EQ(udp.localPort, 15730);
}

TEST(TransportAddress, UdpWithPortAndListenPort) {
    const auto udp = parsedAs<UdpSettings>(QStringLiteral("udp://192.168.1.255:25731?listen=25730"));
    EXPECT_EQ(udp.host, QStringLiteral("192.168.1.255"));
    EXPECT_EQ(udp.remotePort, 25731);
    EXPECT_EQ(udp.localPort, 25730);
}

TEST(TransportAddress, TcpWithAndWithoutPort) {
    EXPECT_EQ(parsedAs<TcpSettings>(QStringLiteral("tcp://cs2")).port, 15731);
    const auto tcp = parsedAs<TcpSettings>(QStringLiteral("tcp://cs2.local:4000"));
    EXPECT_EQ(tcp.host, QStringLiteral("cs2.local"));
    EXPECT_EQ(tcp.port, 4000);
}

TEST(TransportAddress, TcpIpv6AddressInBrackets) {
    const auto tcp = parsedAs<TcpSettings>(QStringLiteral("tcp://[::1]:15731"));
    EXPECT_EQ(tcp.host, QStringLiteral("::1"));
    EXPECT_EQ(transportUrl(tcp), QStringLiteral("tcp://[::1]:15731"));
}

TEST(TransportAddress, CanPluginAndInterface) {
    const auto can = parsedAs<CanBusSettings>(QStringLiteral("can://socketcan/can0"));
    EXPECT_EQ(can.plugin, QStringLiteral("socketcan"));
    EXPECT_EQ(can.interfaceName, QStringLiteral("can0"));
    EXPECT_FALSE(can.bitrate);
}

TEST(TransportAddress, CanWithBitrate) {
    const auto can = parsedAs<CanBusSettings>(QStringLiteral("can://peakcan/usb0?bitrate=250000"));
    EXPECT_EQ(can.plugin, QStringLiteral("peakcan"));
    EXPECT_EQ(can.interfaceName, QStringLiteral("usb0"));
    EXPECT_EQ(can.bitrate, 250000);
}

TEST(TransportAddress, CanInterfaceMayBeAVirtualCanUrl) {
    const auto can = parsedAs<CanBusSettings>(QStringLiteral("can://virtualcan/tcp://127.0.0.1:35468/can1"));
    EXPECT_EQ(can.interfaceName, QStringLiteral("tcp://127.0.0.1:35468/can1"));
}

TEST(TransportAddress, SurroundingSpacesAreIgnored) {
    EXPECT_EQ(parsedAs<TcpSettings>(QStringLiteral("  tcp://cs2  ")).host, QStringLiteral("cs2"));
}

TEST(TransportAddress, BadAddressesSayWhatIsWrong) {
    EXPECT_TRUE(errorOf(QString()).contains(QLatin1String("empty")));
    EXPECT_TRUE(errorOf(QStringLiteral("192.168.1.2")).contains(QLatin1String("udp://, tcp:// or can://")));
    EXPECT_TRUE(errorOf(QStringLiteral("http://cs2")).contains(QLatin1String("unknown transport 'http'")));
    EXPECT_TRUE(errorOf(QStringLiteral("tcp://")).contains(QLatin1String("no host")));
    EXPECT_TRUE(errorOf(QStringLiteral("tcp://cs2:0")).contains(QLatin1String("port 0")));
    EXPECT_FALSE(errorOf(QStringLiteral("tcp://cs2:70000")).isEmpty());
    EXPECT_FALSE(errorOf(QStringLiteral("tcp://cs2:abc")).isEmpty());
    EXPECT_TRUE(errorOf(QStringLiteral("tcp://cs2/config")).contains(QLatin1String("unexpected path")));
    EXPECT_TRUE(
        errorOf(QStringLiteral("tcp://cs2?listen=1")).contains(QLatin1String("unknown option 'listen'")));
    EXPECT_TRUE(errorOf(QStringLiteral("udp://cs2?listen=x")).contains(QLatin1String("listen port 'x'")));
    EXPECT_TRUE(errorOf(QStringLiteral("udp://cs2?listen=65536")).contains(QLatin1String("listen port")));
    EXPECT_TRUE(
        errorOf(QStringLiteral("udp://cs2?lsten=1")).contains(QLatin1String("unknown option 'lsten'")));
    EXPECT_TRUE(errorOf(QStringLiteral("can://socketcan")).contains(QLatin1String("no interface")));
    EXPECT_TRUE(errorOf(QStringLiteral("can://socketcan/")).contains(QLatin1String("no interface")));
    EXPECT_TRUE(errorOf(QStringLiteral("can://socketcan:5/can0")).contains(QLatin1String("no port")));
    EXPECT_TRUE(
        errorOf(QStringLiteral("can://peakcan/usb0?bitrate=fast")).contains(QLatin1String("bitrate 'fast'")));
    EXPECT_TRUE(errorOf(QStringLiteral("tcp://me@cs2")).contains(QLatin1String("user name")));
}

TEST(TransportAddress, ErrorNamesTheAddress) {
    EXPECT_TRUE(errorOf(QStringLiteral("tcp://cs2:0")).startsWith(QLatin1String("'tcp://cs2:0': ")));
}

TEST(TransportAddress, WrittenAddressesReadBackTheSame) {
    for (const char* text : {"udp://192.168.1.2:15731", "udp://cs2:15731?listen=0", "tcp://cs2:15731",
                             "can://socketcan/can0", "can://peakcan/usb0?bitrate=250000"}) {
        const auto settings = parseTransportUrl(QString::fromLatin1(text));
        ASSERT_TRUE(settings.hasValue()) << text;
        EXPECT_EQ(transportUrl(*settings), QString::fromLatin1(text));
        EXPECT_TRUE(*parseTransportUrl(transportUrl(*settings)) == *settings) << text;
    }
}

TEST(TransportFactory, MakesTheTransportTheAddressNames) {
    auto udp = createTransport(QStringLiteral("udp://127.0.0.1:4000?listen=0"));
    ASSERT_TRUE(udp.hasValue());
    ASSERT_NE(dynamic_cast<UdpTransport*>(udp->get()), nullptr);
    EXPECT_EQ(dynamic_cast<UdpTransport*>(udp->get())->settings().remotePort, 4000);
    EXPECT_EQ((*udp)->description(), QStringLiteral("udp://127.0.0.1:4000?listen=0"));

    auto tcp = createTransport(QStringLiteral("tcp://127.0.0.1"));
    ASSERT_TRUE(tcp.hasValue());
    EXPECT_NE(dynamic_cast<TcpTransport*>(tcp->get()), nullptr);
    EXPECT_EQ((*tcp)->description(), QStringLiteral("tcp://127.0.0.1:15731"));
    EXPECT_EQ((*tcp)->state(), Transport::State::Closed) << "made, not opened";

    auto can = createTransport(QStringLiteral("can://virtualcan/can0"));
    ASSERT_TRUE(can.hasValue());
    EXPECT_NE(dynamic_cast<CanBusTransport*>(can->get()), nullptr);
}

TEST(TransportFactory, BadAddressGivesTheReasonAndNoTransport) {
    const auto result = createTransport(QStringLiteral("serial:///dev/ttyUSB0"));
    ASSERT_FALSE(result.hasValue());
    EXPECT_TRUE(result.error().contains(QLatin1String("unknown transport 'serial'")))
        << result.error().toStdString();
}

} // namespace
} // namespace stellwerk::transport::test
