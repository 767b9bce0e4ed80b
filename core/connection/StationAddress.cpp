#include "connection/StationAddress.h"

#include "transport/CanBusTransport.h"
#include "transport/TransportAddress.h"

namespace stellwerk::connection {
namespace {

template <typename Kind>
QString withHost(const Expected<transport::TransportSettings, QString>& current, const QString& host,
                 const QString& scheme) {
    if (host.isEmpty())
        return scheme;
    Kind settings = current && std::holds_alternative<Kind>(*current) ? std::get<Kind>(*current) : Kind{};
    settings.host = host;
    return transport::transportUrl(settings);
}

} // namespace

Expected<StationAddress, QString> StationAddress::read(const QString& text) {
    const auto parsed = transport::parseTransportUrl(text.trimmed());
    if (!parsed)
        return parsed.error();
    StationAddress address;
    if (const auto* udp = std::get_if<transport::UdpSettings>(&*parsed)) {
        address.kind = StationEndpoint::Kind::Udp;
        address.host = udp->host;
    } else if (const auto* tcp = std::get_if<transport::TcpSettings>(&*parsed)) {
        address.kind = StationEndpoint::Kind::Tcp;
        address.host = tcp->host;
    } else {
        const auto& bus = std::get<transport::CanBusSettings>(*parsed);
        address.kind = StationEndpoint::Kind::CanBus;
        address.canInterface = bus.plugin + QLatin1Char('/') + bus.interfaceName;
    }
    return address;
}

StationEndpoint StationAddress::endpointOf(const QString& text) {
    if (text.trimmed().isEmpty())
        return StationEndpoint::simulated();
    const auto parsed = transport::parseTransportUrl(text.trimmed());
    return parsed ? StationEndpoint::of(*parsed) : StationEndpoint::unusable(text);
}

QString StationAddress::atHost(StationEndpoint::Kind kind, const QString& host, const QString& current) {
    const auto parsed = transport::parseTransportUrl(current.trimmed());
    if (kind == StationEndpoint::Kind::Udp)
        return withHost<transport::UdpSettings>(parsed, host.trimmed(), QStringLiteral("udp://"));
    return withHost<transport::TcpSettings>(parsed, host.trimmed(), QStringLiteral("tcp://"));
}

QString StationAddress::ofCanInterface(const QString& canInterface) {
    return QStringLiteral("can://") + canInterface.trimmed();
}

std::vector<CanInterfaceChoice> availableCanInterfaces() {
    std::vector<CanInterfaceChoice> choices;
    for (const transport::CanBusInterface& found : transport::CanBusTransport::availableInterfaces())
        choices.push_back({found.plugin + QLatin1Char('/') + found.name, found.description});
    return choices;
}

} // namespace stellwerk::connection
