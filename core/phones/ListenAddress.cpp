#include "phones/ListenAddress.h"

namespace stellwerk::phones {

std::optional<ListenAddress> ListenAddress::parse(const QString& text, quint16 defaultPort) {
    ListenAddress listen{QHostAddress::Any, defaultPort};
    const QString value = text.trimmed();
    const qsizetype colon = value.lastIndexOf(QLatin1Char(':'));
    const QString host = colon >= 0 ? value.left(colon) : QString();
    const QString port = colon >= 0 ? value.mid(colon + 1) : value;
    if (!host.isEmpty() && !listen.address.setAddress(host))
        return std::nullopt;
    if (port.isEmpty())
        return listen;
    bool ok = false;
    const uint number = port.toUInt(&ok);
    if (!ok || number > 65535)
        return std::nullopt;
    listen.port = quint16(number);
    return listen;
}

QString ListenAddress::text() const {
    if (address == QHostAddress(QHostAddress::Any))
        return QString::number(port);
    return QStringLiteral("%1:%2").arg(address.toString()).arg(port);
}

} // namespace stellwerk::phones
