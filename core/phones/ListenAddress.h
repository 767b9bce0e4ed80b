#pragma once

#include <QHostAddress>
#include <QString>
#include <optional>

namespace stellwerk::phones {

// Where one phone server listens, as `--z21 [HOST:]PORT` and the settings give it: one address (or every
// interface) and a port. Read in one place for the window's flags and the command line's serve.
struct ListenAddress {
    QHostAddress address = QHostAddress::Any;
    quint16 port = 0;

    // "HOST:PORT" or "PORT" (every interface); empty text: `defaultPort` on every interface; nullopt: a host
    // that is no address, or a port that is no number up to 65535.
    static std::optional<ListenAddress> parse(const QString& text, quint16 defaultPort);
    // Back in the form parse() reads: "21105" (every interface) or "192.168.1.20:21105".
    QString text() const;

    friend bool operator==(const ListenAddress&, const ListenAddress&) = default;
};

} // namespace stellwerk::phones
