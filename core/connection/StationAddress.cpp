#include "connection/StationAddress.h"

#include "transport/CanBusTransport.h"
#include "transport/TransportAddress.h"

#include <QCoreApplication>
#include <QUrl>
#include <QUrlQuery>

namespace stellwerk::connection {
namespace {

const QString WebPortKey = QStringLiteral("http");

// The translation context of the messages below.
class Text {
    Q_DECLARE_TR_FUNCTIONS(StationAddress)
};

Expected<StationAddress::Split, QString> splitWebPort(const QString& text) {
    const QString trimmed = text.trimmed();
    QUrl url(trimmed, QUrl::StrictMode);
    QUrlQuery query(url);
    if (!url.isValid() || !query.hasQueryItem(WebPortKey))
        return StationAddress::Split{trimmed, std::nullopt};
    const QString value = query.queryItemValue(WebPortKey);
    bool number = false;
    const uint port = value.toUInt(&number);
    if (!number || port == 0 || port > 65535)
        return Text::tr("web server port '%1' is not a number from 1 to 65535").arg(value);
    if (url.scheme() == QLatin1String("can"))
        return Text::tr("a CAN interface has no web server ('http' is for UDP and TCP stations)");
    query.removeAllQueryItems(WebPortKey);
    url.setQuery(query.isEmpty() ? QString() : query.toString());
    return StationAddress::Split{url.toString(), std::uint16_t(port)};
}

// `address` with `http=<webPort>` added; unchanged for port 0 (none).
QString withWebPort(const QString& address, std::uint16_t webPort) {
    if (webPort == 0)
        return address;
    QUrl url(address);
    QUrlQuery query(url);
    query.addQueryItem(WebPortKey, QString::number(webPort));
    url.setQuery(query);
    return url.toString();
}

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

Expected<StationAddress::Split, QString> StationAddress::split(const QString& text) {
    return splitWebPort(text);
}

QString StationAddress::webServerOf(const QString& text) {
    const auto address = read(text);
    if (!address || address->host.isEmpty())
        return {};
    QUrl url;
    url.setScheme(QStringLiteral("http"));
    url.setHost(address->host);
    if (address->webPort && *address->webPort != StationWebPort)
        url.setPort(*address->webPort);
    return url.isValid() ? url.toString() : QString();
}

Expected<StationAddress, QString> StationAddress::read(const QString& text) {
    const auto split = splitWebPort(text);
    if (!split)
        return split.error();
    const auto parsed = transport::parseTransportUrl(split->transport);
    if (!parsed)
        return parsed.error();
    StationAddress address;
    address.webPort = split->webPort;
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
    const auto split = splitWebPort(text);
    const auto parsed = split ? transport::parseTransportUrl(split->transport)
                              : Expected<transport::TransportSettings, QString>(split.error());
    return parsed ? StationEndpoint::of(*parsed) : StationEndpoint::unusable(text);
}

QString StationAddress::atHost(StationEndpoint::Kind kind, const QString& host, const QString& current) {
    const auto split = splitWebPort(current);
    const QString rest = split ? split->transport : current.trimmed();
    const std::uint16_t webPort = split && !host.trimmed().isEmpty() ? split->webPort.value_or(0) : 0;
    const auto parsed = transport::parseTransportUrl(rest);
    if (kind == StationEndpoint::Kind::Udp)
        return withWebPort(withHost<transport::UdpSettings>(parsed, host.trimmed(), QStringLiteral("udp://")),
                           webPort);
    return withWebPort(withHost<transport::TcpSettings>(parsed, host.trimmed(), QStringLiteral("tcp://")),
                       webPort);
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
