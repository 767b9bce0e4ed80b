#include "transport/TransportAddress.h"

#include <QCoreApplication>
#include <QUrl>
#include <QUrlQuery>
#include <optional>

namespace stellwerk::transport {

namespace {

using Result = Expected<TransportSettings, QString>;

// The translation context of the messages below.
class Text {
    Q_DECLARE_TR_FUNCTIONS(TransportAddress)
};

// A port number from the address text; 0 only where `zeroAllowed`.
std::optional<std::uint16_t> readPort(const QString& text, bool zeroAllowed) {
    bool ok = false;
    const uint port = text.toUInt(&ok);
    if (!ok || port > 65535 || (port == 0 && !zeroAllowed))
        return std::nullopt;
    return std::uint16_t(port);
}

// What every address needs: a host, no user, no fragment; a path only where `pathAllowed`.
std::optional<QString> checkShape(const QUrl& url, bool pathAllowed) {
    if (url.host().isEmpty())
        return Text::tr("no host");
    if (!url.userInfo().isEmpty())
        return Text::tr("a user name has no place in a transport address");
    if (url.hasFragment())
        return Text::tr("a '#' part has no place in a transport address");
    if (!pathAllowed && !url.path().isEmpty() && url.path() != QLatin1String("/"))
        return Text::tr("unexpected path '%1'").arg(url.path());
    return std::nullopt;
}

// Query items other than `allowed` are mistakes, reported rather than ignored.
std::optional<QString> checkQueryKeys(const QUrlQuery& query, const QString& allowed) {
    for (const auto& [key, value] : query.queryItems()) {
        if (key != allowed)
            return allowed.isEmpty() ? Text::tr("unknown option '%1'").arg(key)
                                     : Text::tr("unknown option '%1' (only '%2' is known)").arg(key, allowed);
    }
    return std::nullopt;
}

std::optional<QString> readStationPort(const QUrl& url, std::uint16_t& port) {
    if (url.port() == -1)
        return std::nullopt;
    if (url.port() == 0)
        return Text::tr("port 0 cannot be connected to");
    port = std::uint16_t(url.port());
    return std::nullopt;
}

std::optional<QString> readListenPort(const QUrlQuery& query, std::uint16_t& port) {
    if (!query.hasQueryItem(QStringLiteral("listen")))
        return std::nullopt;
    const QString value = query.queryItemValue(QStringLiteral("listen"));
    const auto listen = readPort(value, true);
    if (!listen)
        return Text::tr("listen port '%1' is not a number from 0 to 65535").arg(value);
    port = *listen;
    return std::nullopt;
}

std::optional<QString> readBitrate(const QUrlQuery& query, std::optional<int>& bitrate) {
    if (!query.hasQueryItem(QStringLiteral("bitrate")))
        return std::nullopt;
    bool ok = false;
    const QString value = query.queryItemValue(QStringLiteral("bitrate"));
    const int number = value.toInt(&ok);
    if (!ok || number <= 0)
        return Text::tr("bitrate '%1' is not a positive number").arg(value);
    bitrate = number;
    return std::nullopt;
}

Result parseUdp(const QUrl& url) {
    UdpSettings settings;
    settings.host = url.host();
    const QUrlQuery query(url);
    if (auto error = checkShape(url, false))
        return Result(*error);
    if (auto error = checkQueryKeys(query, QStringLiteral("listen")))
        return Result(*error);
    if (auto error = readStationPort(url, settings.remotePort))
        return Result(*error);
    if (auto error = readListenPort(query, settings.localPort))
        return Result(*error);
    return Result(TransportSettings(settings));
}

Result parseTcp(const QUrl& url) {
    TcpSettings settings;
    settings.host = url.host();
    if (auto error = checkShape(url, false))
        return Result(*error);
    if (auto error = checkQueryKeys(QUrlQuery(url), QString()))
        return Result(*error);
    if (auto error = readStationPort(url, settings.port))
        return Result(*error);
    return Result(TransportSettings(settings));
}

Result parseCanBus(const QUrl& url) {
    CanBusSettings settings;
    settings.plugin = url.host();
    settings.interfaceName = url.path(QUrl::FullyDecoded).mid(1);
    const QUrlQuery query(url);
    if (auto error = checkShape(url, true))
        return Result(*error);
    if (auto error = checkQueryKeys(query, QStringLiteral("bitrate")))
        return Result(*error);
    if (url.port() != -1)
        return Result(Text::tr("a CAN plugin has no port"));
    if (settings.interfaceName.isEmpty())
        return Result(
            Text::tr("no interface (write can://plugin/interface, for example can://socketcan/can0)"));
    if (auto error = readBitrate(query, settings.bitrate))
        return Result(*error);
    return Result(TransportSettings(settings));
}

Result parseUrl(const QString& text) {
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid())
        return Result(url.errorString());
    const QString scheme = url.scheme();
    if (scheme == QLatin1String("udp"))
        return parseUdp(url);
    if (scheme == QLatin1String("tcp"))
        return parseTcp(url);
    if (scheme == QLatin1String("can"))
        return parseCanBus(url);
    if (scheme.isEmpty())
        return Result(Text::tr("no transport (start with udp://, tcp:// or can://)"));
    return Result(Text::tr("unknown transport '%1' (use udp://, tcp:// or can://)").arg(scheme));
}

QUrl stationUrl(const QString& scheme, const QString& host, std::uint16_t port) {
    QUrl url;
    url.setScheme(scheme);
    url.setHost(host);
    url.setPort(port);
    return url;
}

} // namespace

Result parseTransportUrl(const QString& text) {
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return Result(Text::tr("the transport address is empty"));
    Result result = parseUrl(trimmed);
    if (!result)
        return Result(Text::tr("'%1': %2").arg(trimmed, result.error()));
    return result;
}

QString transportUrl(const UdpSettings& settings) {
    QUrl url = stationUrl(QStringLiteral("udp"), settings.host, settings.remotePort);
    if (settings.localPort != ListenPort)
        url.setQuery(QStringLiteral("listen=%1").arg(settings.localPort));
    return url.toString();
}

QString transportUrl(const TcpSettings& settings) {
    return stationUrl(QStringLiteral("tcp"), settings.host, settings.port).toString();
}

QString transportUrl(const CanBusSettings& settings) {
    QUrl url;
    url.setScheme(QStringLiteral("can"));
    url.setHost(settings.plugin);
    url.setPath(QLatin1Char('/') + settings.interfaceName);
    if (settings.bitrate)
        url.setQuery(QStringLiteral("bitrate=%1").arg(*settings.bitrate));
    return url.toString();
}

QString transportUrl(const TransportSettings& settings) {
    return std::visit([](const auto& each) { return transportUrl(each); }, settings);
}

} // namespace stellwerk::transport
