#pragma once

#include "transport/TransportSettings.h"

#include <QString>

namespace stellwerk::connection {

// Which station the app talks to, in the words a person uses: the embedded simulator, or a CS2 reached
// by UDP or TCP, or a CAN interface. The UI builds its own (translated) wording from kind and place.
struct StationEndpoint {
    enum class Kind { Simulated, Udp, Tcp, CanBus, Unusable };

    Kind kind = Kind::Simulated;
    QString place; // "192.168.2.5", "192.168.2.5:15732", "socketcan/can0"; the text as typed when Unusable

    static StationEndpoint simulated();
    static StationEndpoint of(const transport::TransportSettings& settings);
    static StationEndpoint unusable(const QString& text);

    // "Simulated CS2 (demo layout)", "CS2 at 192.168.2.5 (UDP)", "CAN interface socketcan/can0".
    QString description() const;

    friend bool operator==(const StationEndpoint&, const StationEndpoint&) = default;
};

} // namespace stellwerk::connection
