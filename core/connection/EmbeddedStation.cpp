#include "connection/EmbeddedStation.h"

#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "sim/TrainMovement.h"
#include "sim/TrainTrack.h"

namespace stellwerk::connection {

EmbeddedStation::EmbeddedStation() = default;

// Trains first (they drive the station), then the server (it forwards the station's frames).
EmbeddedStation::~EmbeddedStation() {
    trains_.reset();
    server_.reset();
    station_.reset();
}

bool EmbeddedStation::start() {
    sim::StationLayout layout = sim::StationLayout::demo();
    if (layout.files().empty()) {
        error_ = QStringLiteral("the demo layout is not built into this program");
        return false;
    }
    station_ = std::make_unique<sim::SimulatedStation>(std::move(layout));
    sim::StationServerSettings settings;
    settings.listenAddress = QHostAddress(QHostAddress::LocalHost);
    settings.udp = false;
    settings.tcpPort = 0;
    server_ = std::make_unique<sim::StationServer>(*station_, settings);
    if (!server_->listen()) {
        error_ = server_->errorString();
        return false;
    }
    trains_ = std::make_unique<sim::TrainMovement>(*station_, sim::TrainTrack::demo());
    trains_->start();
    return true;
}

std::uint16_t EmbeddedStation::tcpPort() const {
    return server_ ? server_->tcpPort() : 0;
}

QString EmbeddedStation::url() const {
    return QStringLiteral("tcp://127.0.0.1:%1").arg(tcpPort());
}

} // namespace stellwerk::connection
