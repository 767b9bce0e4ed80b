#pragma once

#include <QString>
#include <cstdint>
#include <memory>

namespace stellwerk::sim {
class SimulatedStation;
class StationServer;
class TrainMovement;
} // namespace stellwerk::sim

namespace stellwerk::connection {

// The simulated CS2 the app uses when no station is configured: the demo layout with track power on and
// two trains running round the loop (a real station is never commanded on start), listening for TCP on a free
// port of 127.0.0.1, so that the app reaches it through a real transport like any other station (never as a
// shortcut inside the app).
class EmbeddedStation final {
public:
    // The UID of an mfx decoder on the demo's track that is not registered yet, for trying discovery.
    static constexpr std::uint32_t NewMfxDecoder = 0x7a3c1e10;

    EmbeddedStation();
    ~EmbeddedStation();
    EmbeddedStation(const EmbeddedStation&) = delete;
    EmbeddedStation& operator=(const EmbeddedStation&) = delete;

    // Builds the station and starts listening; false (with errorString()) when that is not possible.
    bool start();
    QString errorString() const { return error_; }
    // The TCP port it listens on (0 before start()).
    std::uint16_t tcpPort() const;
    // The address a TcpTransport connects to: "tcp://127.0.0.1:<port>".
    QString url() const;

    sim::SimulatedStation* station() const { return station_.get(); }

private:
    std::unique_ptr<sim::SimulatedStation> station_;
    std::unique_ptr<sim::StationServer> server_;
    std::unique_ptr<sim::TrainMovement> trains_;
    QString error_;
};

} // namespace stellwerk::connection
