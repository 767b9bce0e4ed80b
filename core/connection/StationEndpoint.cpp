#include "connection/StationEndpoint.h"

namespace stellwerk::connection {
namespace {

// The host, with the port only when it is not the CS2's usual one.
QString hostAndPort(const QString& host, std::uint16_t port) {
    return port == transport::StationPort ? host : QStringLiteral("%1:%2").arg(host).arg(port);
}

} // namespace

StationEndpoint StationEndpoint::simulated() {
    return {Kind::Simulated, QString()};
}

StationEndpoint StationEndpoint::of(const transport::TransportSettings& settings) {
    if (const auto* udp = std::get_if<transport::UdpSettings>(&settings))
        return {Kind::Udp, hostAndPort(udp->host, udp->remotePort)};
    if (const auto* tcp = std::get_if<transport::TcpSettings>(&settings))
        return {Kind::Tcp, hostAndPort(tcp->host, tcp->port)};
    const auto& bus = std::get<transport::CanBusSettings>(settings);
    return {Kind::CanBus, QStringLiteral("%1/%2").arg(bus.plugin, bus.interfaceName)};
}

StationEndpoint StationEndpoint::unusable(const QString& text) {
    return {Kind::Unusable, text};
}

QString StationEndpoint::description() const {
    switch (kind) {
    case Kind::Simulated:
        return QStringLiteral("Simulated CS2 (demo layout)");
    case Kind::Udp:
        return QStringLiteral("CS2 at %1 (UDP)").arg(place);
    case Kind::Tcp:
        return QStringLiteral("CS2 at %1 (TCP)").arg(place);
    case Kind::CanBus:
        return QStringLiteral("CAN interface %1").arg(place);
    case Kind::Unusable:
        break;
    }
    return QStringLiteral("Station \"%1\"").arg(place);
}

} // namespace stellwerk::connection
