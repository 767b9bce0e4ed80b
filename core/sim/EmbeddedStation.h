#pragma once

#include "transport/LocalPeer.h"

#include <QString>
#include <QTimer>
#include <cstdint>
#include <functional>
#include <memory>

namespace stellwerk::sim {

class BusGateway;
class HttpConfigServer;
class SimulatedOrcDecoder;
class SimulatedOrcEncoder;
class SimulatedRoModule;
class SimulatedBus;
class SimulatedMs1;
class SimulatedStation;
class StationHandhelds;
class StationServer;
class TrainMovement;

// The simulated CS2 the app uses when no station is configured: the demo layout with track power on and
// two trains running round the loop (a real station is never commanded on start), listening for TCP on a free
// port of 127.0.0.1, so that the app reaches it through a real transport like any other station (never as a
// shortcut inside the app). The GUI program hands it to the connection layer as its local peer.
class EmbeddedStation final : public transport::LocalPeer {
public:
    // The UID of an mfx decoder on the demo's track that is not registered yet, for trying discovery.
    static constexpr std::uint32_t NewMfxDecoder = 0x7a3c1e10;
    // The UID of the demo's MS1 handheld.
    static constexpr std::uint32_t DemoHandheld = 0x000204B3;
    // The demo's devices on its device bus (deviceBuses()): an OpenRailCAN 8-output decoder and 32-input
    // encoder (UIDs of developer 0x3A2E, "Michael F. Schwarzer" in the document's example) and RO module 1
    // of the simulator's profile (ro::RoProfile::simulator(1)).
    static constexpr std::uint32_t DemoOrcDecoder = 0x3A2E0101;
    static constexpr std::uint32_t DemoOrcEncoder = 0x3A2E0102;
    // The S88 contact of the demo's siding (Abstellgleis), whose occupancy the encoder's input 0 reports.
    static constexpr std::uint16_t DemoSidingContact = 9;

    // Makes a new embedded station for each connection that asks for the simulated one.
    static transport::LocalPeerFactory factory();

    EmbeddedStation();
    ~EmbeddedStation() override;
    EmbeddedStation(const EmbeddedStation&) = delete;
    EmbeddedStation& operator=(const EmbeddedStation&) = delete;

    // Builds the station and starts listening; false (with errorString()) when that is not possible.
    bool start() override;
    QString errorString() const override { return error_; }
    // "tcp" to 127.0.0.1 and tcpPort().
    transport::TransportSettings address() const override;
    // The TCP port it listens on (0 before start()).
    std::uint16_t tcpPort() const;
    // The address a TcpTransport connects to: "tcp://127.0.0.1:<port>".
    QString url() const;
    // Its web server with the files and the locomotive pictures: "http://127.0.0.1:<port>".
    QString webAddress() const override;
    // The gateway of its device bus: "tcp" to 127.0.0.1 and the gateway's port.
    std::vector<transport::TransportSettings> deviceBuses() const override;
    SimulatedRoModule* roModule() const { return roModule_.get(); }
    SimulatedOrcDecoder* orcDecoder() const { return decoder_.get(); }
    SimulatedOrcEncoder* orcEncoder() const { return encoder_.get(); }

    SimulatedStation* station() const { return station_.get(); }
    // The demo's MS1 handheld on the station's bus (it logs in to the station, which is its master, and takes
    // the first locomotive of its stack), and the station's master side.
    SimulatedMs1* handheld() const { return handheld_.get(); }
    StationHandhelds* handhelds() const { return handhelds_.get(); }

    // Which train is on which contact, as the simulation moves them (locId 0: none any more). A real
    // station cannot say this; the GUI program shows the demo's trains on its plan with it. Set before
    // start(): the trains' first places are told during start().
    using OccupantReport =
        std::function<void(std::uint16_t device, std::uint16_t contact, std::uint32_t locId)>;
    void reportOccupants(OccupantReport report) { report_ = std::move(report); }

private:
    void putOnBus();
    bool startDeviceBus();
    bool startWebServer();
    void wireSidingToEncoder();

    std::unique_ptr<SimulatedBus> bus_;
    std::unique_ptr<SimulatedStation> station_;
    std::unique_ptr<StationHandhelds> handhelds_;
    std::unique_ptr<SimulatedMs1> handheld_;
    std::unique_ptr<StationServer> server_;
    std::unique_ptr<HttpConfigServer> web_;
    std::unique_ptr<TrainMovement> trains_;
    std::unique_ptr<SimulatedBus> deviceBus_;
    std::unique_ptr<SimulatedRoModule> roModule_;
    std::unique_ptr<SimulatedOrcDecoder> decoder_;
    std::unique_ptr<SimulatedOrcEncoder> encoder_;
    std::unique_ptr<BusGateway> gateway_;
    std::unique_ptr<QTimer> moduleInput_; // the module's input 1 changes now and then
    OccupantReport report_;
    QString error_;
};

} // namespace stellwerk::sim
