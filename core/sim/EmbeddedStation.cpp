#include "sim/EmbeddedStation.h"

#include "cs2/Codec.h"
#include "cs2/Request.h"
#include "sim/BusGateway.h"
#include "sim/HttpConfigServer.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedMs1.h"
#include "sim/SimulatedOrcDevices.h"
#include "sim/SimulatedRoModule.h"
#include "sim/SimulatedStation.h"
#include "sim/StationHandhelds.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "sim/TrainMovement.h"
#include "sim/TrainPlacement.h"

namespace stellwerk::sim {

namespace {

// The demo's trains that run when the app starts: BR 218 Ost and ICE 3 Velaro, both placed on the loop
// (Gleis 1 - Ausfahrt Ost - Block 1..4 - Einfahrt West with the turnouts straight, as in
// magnetartikel.cs2), at the same moderate speed (300 mm/s) so that they keep their distance. A contact
// changes every second or two.
struct DemoRun {
    std::uint32_t locId;
    std::uint16_t speed; // 0..1000
};
constexpr DemoRun DemoRuns[] = {{0x4001, 600}, {0x4002, 600}};
constexpr std::uint8_t Headlights = 0; // F0
constexpr int ModuleInputPeriodMs = 5000;

// Commands the station as a controller on the bus would, before anyone connects.
void command(SimulatedStation& station, cs2::MessageBody body) {
    station.receive(cs2::encode(cs2::request(std::move(body))));
}

void startDemoTrains(SimulatedStation& station) {
    for (const DemoRun& run : DemoRuns) {
        command(station, cs2::LocoFunction{cs2::LocId(run.locId), Headlights, std::uint8_t(1), {}});
        command(station, cs2::LocoSpeed{cs2::LocId(run.locId), run.speed});
    }
}

} // namespace

transport::LocalPeerFactory EmbeddedStation::factory() {
    return [] { return std::make_unique<EmbeddedStation>(); };
}

EmbeddedStation::EmbeddedStation() = default;

// Trains first (they drive the station), then the server (it forwards the station's frames).
EmbeddedStation::~EmbeddedStation() {
    moduleInput_.reset();
    gateway_.reset();
    encoder_.reset();
    decoder_.reset();
    roModule_.reset();
    deviceBus_.reset();
    trains_.reset();
    web_.reset();
    server_.reset();
    handheld_.reset();
    handhelds_.reset();
    station_.reset();
    bus_.reset();
}

bool EmbeddedStation::start() {
    StationLayout layout = StationLayout::demo();
    if (layout.files().empty()) {
        error_ = QStringLiteral("the demo layout is not built into this program");
        return false;
    }
    SimulatedStation::Options options;
    options.power = SimulatedStation::Power::Running; // the demo is alive; a real CS2 starts in STOP
    options.newMfxDecoders = {NewMfxDecoder};         // a new mfx loco waits to be discovered
    station_ = std::make_unique<SimulatedStation>(std::move(layout), options);
    startDemoTrains(*station_);
    StationServerSettings settings;
    settings.listenAddress = QHostAddress(QHostAddress::LocalHost);
    settings.udp = false;
    settings.tcpPort = 0;
    // The CS2 protocol has no query for the track power: the station tells a controller that connects
    // what it is now (Stop, Go or Halt) and never switches it for them, so a station whose power was
    // turned off stays off for a controller that comes back.
    settings.announcePowerToNewClients = true;
    putOnBus();
    server_ = std::make_unique<StationServer>(*station_, *bus_, settings);
    if (!server_->listen()) {
        error_ = server_->errorString();
        return false;
    }
    handheld_->plugIn();
    if (!startWebServer() || !startDeviceBus())
        return false;
    trains_ = std::make_unique<TrainMovement>(*station_, demoPlacements());
    wireSidingToEncoder();
    if (report_)
        QObject::connect(trains_.get(), &TrainMovement::occupantChanged, trains_.get(), report_);
    trains_->start();
    return true;
}

// The station, its master side for the MS1 handhelds and the demo's MS1 on one bus, as on a real CS2's.
void EmbeddedStation::putOnBus() {
    bus_ = std::make_unique<SimulatedBus>();
    bus_->attach(*station_);
    handhelds_ = std::make_unique<StationHandhelds>(*station_);
    bus_->attach(*handhelds_);
    SimulatedMs1::Options demo;
    demo.identity.uid = DemoHandheld;
    demo.identity.name = "Demo MS1";
    handheld_ = std::make_unique<SimulatedMs1>(demo);
    bus_->attach(*handheld_);
}

// The station's web server on a free loopback port: the files below /config/, the pictures below /icons/.
bool EmbeddedStation::startWebServer() {
    const SimulatedStation* station = station_.get();
    web_ = std::make_unique<HttpConfigServer>(
        [station](std::string_view path) { return station->layout().fileForPath(path); },
        [station](std::string_view name) { return station->layout().pictureFor(name); });
    if (!web_->listen(QHostAddress(QHostAddress::LocalHost), 0)) {
        error_ = web_->errorString();
        return false;
    }
    return true;
}

// The demo's devices on a bus of their own behind a gateway: OpenRailCAN and the MS1 handheld cannot share
// one bus (notes O26), and a real layout would put them on a USB-CAN adapter's bus the same way.
bool EmbeddedStation::startDeviceBus() {
    deviceBus_ = std::make_unique<SimulatedBus>();
    roModule_ = std::make_unique<SimulatedRoModule>(ro::RoProfile::simulator(1));
    decoder_ = std::make_unique<SimulatedOrcDecoder>(DemoOrcDecoder);
    encoder_ = std::make_unique<SimulatedOrcEncoder>(DemoOrcEncoder);
    deviceBus_->attach(*roModule_);
    deviceBus_->attach(*decoder_);
    deviceBus_->attach(*encoder_);
    decoder_->plugIn();
    encoder_->plugIn();
    gateway_ = std::make_unique<BusGateway>(*deviceBus_);
    if (!gateway_->listen()) {
        error_ = gateway_->errorString();
        return false;
    }
    moduleInput_ = std::make_unique<QTimer>();
    QObject::connect(moduleInput_.get(), &QTimer::timeout,
                     [this] { roModule_->setInput(1, !roModule_->input(1)); }); // a switch on the desk
    moduleInput_->start(ModuleInputPeriodMs);
    return true;
}

// The siding's occupancy detector is wired to the encoder's input 0, which DeviceBindings::demo() binds to
// the siding's contact: the contact is lit while a train stands there (the Köf from the start), as an S88
// contact would be, only reported by the encoder. Connected before the trains are placed.
void EmbeddedStation::wireSidingToEncoder() {
    QObject::connect(trains_.get(), &TrainMovement::occupantChanged, trains_.get(),
                     [this](std::uint16_t device, std::uint16_t contact, std::uint32_t locId) {
                         if (device == 0 && contact == DemoSidingContact && encoder_)
                             encoder_->setInput(0, locId != 0);
                     });
}

std::vector<transport::TransportSettings> EmbeddedStation::deviceBuses() const {
    if (!gateway_)
        return {};
    transport::TcpSettings tcp;
    tcp.host = QStringLiteral("127.0.0.1");
    tcp.port = gateway_->port();
    return {tcp};
}

QString EmbeddedStation::webAddress() const {
    return web_ ? QStringLiteral("http://127.0.0.1:%1").arg(web_->port()) : QString();
}

std::uint16_t EmbeddedStation::tcpPort() const {
    return server_ ? server_->tcpPort() : 0;
}

transport::TransportSettings EmbeddedStation::address() const {
    transport::TcpSettings tcp;
    tcp.host = QStringLiteral("127.0.0.1");
    tcp.port = tcpPort();
    return tcp;
}

QString EmbeddedStation::url() const {
    return QStringLiteral("tcp://127.0.0.1:%1").arg(tcpPort());
}

} // namespace stellwerk::sim
