#pragma once

#include "base/Expected.h"
#include "connection/StationEndpoint.h"

#include <QString>
#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::connection {

// A station's address as a person types it ("udp://192.168.2.5", "tcp://cs2:15731", "can://socketcan/can0"),
// read into the parts the Connect dialog shows, and built back from them; the dialog never sees a
// transport's settings.
//
// Beside what the transport reads, an address of a UDP or TCP station may say where the station's web
// server is (its files and the locomotive pictures): `?http=8080`. A CS2 or CS3 serves them on port 80 of
// the same host; a simulator (`stellwerk-sim --http-port 8080`) or a gateway may use another port.
struct StationAddress {
    // A Central Station's web server port.
    static constexpr std::uint16_t StationWebPort = 80;

    StationEndpoint::Kind kind = StationEndpoint::Kind::Unusable;
    QString host;                         // UDP and TCP
    QString canInterface;                 // "socketcan/can0" for a CAN interface
    std::optional<std::uint16_t> webPort; // `http=<port>`; StationWebPort when not given

    // The parts of an address, or why it cannot be used.
    static Expected<StationAddress, QString> read(const QString& text);
    // An address taken apart: what the transport reads, and the `http` option.
    struct Split {
        QString transport;
        std::optional<std::uint16_t> webPort;
    };
    // The address as the transport reads it (without the `http` option; the text itself when it has
    // none) and the web server port; why not when that option is not a port or names a web server for a
    // CAN interface (which has none).
    static Expected<Split, QString> split(const QString& text);
    // The station's web server at the address: "http://192.168.2.5" (port 80), or the port the `http`
    // option names ("tcp://127.0.0.1:15731?http=8080" gives "http://127.0.0.1:8080"); empty for a CAN
    // interface or an address that cannot be used.
    static QString webServerOf(const QString& text);
    // What the address names, in a person's words; empty text is the simulated station.
    static StationEndpoint endpointOf(const QString& text);
    // The address of a UDP or TCP station at `host`, keeping what `current` says beyond the host (its ports
    // and web server port) when it is of the same kind; just the scheme ("udp://") while there is no host.
    static QString atHost(StationEndpoint::Kind kind, const QString& host, const QString& current);
    // The address of a CAN interface ("socketcan/can0").
    static QString ofCanInterface(const QString& canInterface);
};

// A CAN interface a person can choose: "socketcan/can0" and what its driver says about it.
struct CanInterfaceChoice {
    QString name;
    QString description;
};

// The CAN interfaces Qt's plugins find on this machine now.
std::vector<CanInterfaceChoice> availableCanInterfaces();

} // namespace stellwerk::connection
