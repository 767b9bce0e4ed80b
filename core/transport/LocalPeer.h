#pragma once

#include "transport/TransportSettings.h"

#include <QString>
#include <functional>
#include <memory>
#include <vector>

namespace stellwerk::transport {

// A peer that this program runs itself (the embedded simulated CS2) and still reaches through a real
// transport, like any station on the network. Whoever builds the program decides which peer that is,
// so the layers that use it never link the simulator.
class LocalPeer {
public:
    virtual ~LocalPeer() = default;

    // Starts the peer; false (with errorString()) when that is not possible.
    virtual bool start() = 0;
    virtual QString errorString() const = 0;
    // Where a transport reaches the started peer.
    virtual TransportSettings address() const = 0;
    // Where the started peer serves files over HTTP like a station's web server ("http://127.0.0.1:8080"),
    // empty when it serves none.
    virtual QString webAddress() const { return {}; }
    // Further buses the started peer has devices on (the embedded station's OpenRailCAN devices and RO
    // module), reached like a further bus; none by default.
    virtual std::vector<TransportSettings> deviceBuses() const { return {}; }
};

// Makes a new local peer for each connection; empty when the program has none.
using LocalPeerFactory = std::function<std::unique_ptr<LocalPeer>()>;

} // namespace stellwerk::transport
