#pragma once

#include "base/Expected.h"
#include "connection/StationEndpoint.h"

#include <QString>
#include <vector>

namespace stellwerk::connection {

// A station's address as a person types it ("udp://192.168.2.5", "tcp://cs2:15731", "can://socketcan/can0"),
// read into the parts the Connect dialog shows, and built back from them; the dialog never sees a
// transport's settings.
struct StationAddress {
    StationEndpoint::Kind kind = StationEndpoint::Kind::Unusable;
    QString host;         // UDP and TCP
    QString canInterface; // "socketcan/can0" for a CAN interface

    // The parts of an address, or why it cannot be used.
    static Expected<StationAddress, QString> read(const QString& text);
    // What the address names, in a person's words; empty text is the simulated station.
    static StationEndpoint endpointOf(const QString& text);
    // The address of a UDP or TCP station at `host`, keeping what `current` says beyond the host (its ports)
    // when it is of the same kind; just the scheme ("udp://") while there is no host.
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
