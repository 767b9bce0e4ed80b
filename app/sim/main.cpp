// stellwerk-sim: the simulated CS2 as a process, for other programs (and Stellwerk itself) to talk to
// over UDP, TCP, HTTP and optionally a CAN interface; with --ms1 N, MS1 handhelds share its bus, with --ro N,
// RO relay/IO modules, with --orc-booster, --orc-decoders N and --orc-encoders N, OpenRailCAN devices.

#include "ShutdownSignal.h"
#include "SimOptions.h"
#include "SimOrcDevices.h"
#include "sim/HttpConfigServer.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedMs1.h"
#include "sim/SimulatedRoModule.h"
#include "sim/SimulatedStation.h"
#include "sim/StationHandhelds.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "sim/TrainMovement.h"
#include "sim/TrainPlacement.h"

#include <QCoreApplication>
#include <QTextStream>
#include <QTimer>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace stellwerk;

QTextStream& out() {
    static QTextStream stream(stdout);
    return stream;
}

QTextStream& err() {
    static QTextStream stream(stderr);
    return stream;
}

std::optional<sim::StationLayout> loadLayout(const simapp::SimOptions& options) {
    if (options.layoutDirectory.isEmpty())
        return sim::StationLayout::demo();
    cs2config::Diagnostics diagnostics(options.layoutDirectory.toStdString());
    sim::StationLayout layout = sim::StationLayout::load(options.layoutDirectory.toStdString(), diagnostics);
    for (const std::string& line : layout.diagnostics())
        err() << QString::fromStdString(line) << Qt::endl;
    if (layout.files().empty()) {
        err() << "stellwerk-sim: no configuration files in " << options.layoutDirectory << Qt::endl;
        return std::nullopt;
    }
    return layout;
}

// The trains of --place, else the demo's, else the first locomotives spread over the blocks.
std::vector<sim::TrainPlacement> placementsFor(const simapp::SimOptions& options,
                                               const sim::StationLayout& layout,
                                               const trackgraph::TrackGraph& graph) {
    if (!options.placements.empty())
        return options.placements;
    if (options.layoutDirectory.isEmpty())
        return sim::demoPlacements();
    return sim::spreadPlacements(layout.locomotives(), graph);
}

// Everything the running simulator owns, torn down in reverse order when the event loop ends. The bus
// exists with handhelds or with the station as their master: without either, the station is alone behind
// its server.
struct Simulator {
    std::unique_ptr<sim::SimulatedBus> bus;
    std::unique_ptr<sim::SimulatedStation> station;
    std::unique_ptr<sim::StationHandhelds> master;
    std::vector<std::unique_ptr<sim::SimulatedMs1>> handhelds;
    std::vector<std::unique_ptr<sim::SimulatedRoModule>> roModules;
    std::unique_ptr<QTimer> roInputs; // an input of each RO module changes now and then
    std::unique_ptr<simapp::SimOrcDevices> orcDevices;
    std::unique_ptr<sim::StationServer> server;
    std::unique_ptr<sim::HttpConfigServer> http;
    std::unique_ptr<sim::TrainMovement> trains;
};

// The first has the chapter-11 trace's UID; the others follow it, so that their UIDs begin alike, as two MS1s
// of one production run do.
constexpr std::uint32_t FirstHandheldUid = 0x000204B3;

void reportHandheld(const sim::SimulatedMs1& ms1) {
    const QString name = QString::fromStdString(ms1.identity().name);
    QObject::connect(&ms1, &sim::SimulatedMs1::loggedIn, &ms1,
                     [name](int node) { out() << name << ": logged in as node " << node << Qt::endl; });
    QObject::connect(&ms1, &sim::SimulatedMs1::locoTaken, &ms1, [name, &ms1](int index) {
        out() << name << ": drives " << QString::fromStdString(ms1.memory().stack[std::size_t(index)].name)
              << Qt::endl;
    });
    QObject::connect(&ms1, &sim::SimulatedMs1::masterLost, &ms1,
                     [name] { out() << name << ": no master" << Qt::endl; });
    QObject::connect(&ms1, &sim::SimulatedMs1::flashModeEntered, &ms1,
                     [name] { out() << name << ": told to flash; in its boot loader now" << Qt::endl; });
}

// RO modules 1..N on the bus with the simulator profile; their relays are printed as requests switch them,
// and every 2 s one of their inputs changes, so that a poller has something to see.
void addRoModules(Simulator& simulator, const simapp::SimOptions& options) {
    for (int n = 1; n <= options.roModules; ++n) {
        auto& module = simulator.roModules.emplace_back(
            std::make_unique<sim::SimulatedRoModule>(ro::RoProfile::simulator(std::uint16_t(n))));
        module->setAnswerDelay(options.roDelay);
        module->loseEveryAnswer(options.roLoseEvery);
        simulator.bus->attach(*module);
        QObject::connect(module.get(), &sim::SimulatedRoModule::relaysChanged, module.get(),
                         [n](std::uint32_t relays) {
                             out() << "RO module " << n << ": relays "
                                   << QString::number(relays, 2).rightJustified(16, '0') << Qt::endl;
                         });
    }
    if (simulator.roModules.empty())
        return;
    simulator.roInputs = std::make_unique<QTimer>();
    QObject::connect(simulator.roInputs.get(), &QTimer::timeout, [&simulator, tick = 0]() mutable {
        const int input = 1 + tick++ % 16;
        for (const auto& module : simulator.roModules)
            module->setInput(input, !module->input(input));
    });
    simulator.roInputs->start(2000);
    out() << "RO modules: " << simulator.roModules.size()
          << " on the bus (requests 0x01FE0001.., answers 0x01FF0001..)" << Qt::endl;
}

// The handhelds and the station on one bus, which the server puts on the network.
void addHandhelds(Simulator& simulator, const simapp::SimOptions& options) {
    simulator.bus = std::make_unique<sim::SimulatedBus>();
    simulator.bus->attach(*simulator.station);
    if (options.handheldMaster) { // a CS2 answers the MS1s itself
        simulator.master = std::make_unique<sim::StationHandhelds>(*simulator.station);
        simulator.bus->attach(*simulator.master);
    }
    for (int i = 0; i < options.handhelds; ++i) {
        sim::SimulatedMs1::Options handheld;
        handheld.identity.uid = FirstHandheldUid + std::uint32_t(i);
        handheld.identity.name = "MS1 " + std::to_string(i + 1);
        handheld.drivesNowAndThen = true;
        auto& ms1 = simulator.handhelds.emplace_back(std::make_unique<sim::SimulatedMs1>(handheld));
        simulator.bus->attach(*ms1);
        reportHandheld(*ms1);
    }
    addRoModules(simulator, options);
    simulator.orcDevices = std::make_unique<simapp::SimOrcDevices>(*simulator.bus, options);
    simulator.server =
        std::make_unique<sim::StationServer>(*simulator.station, *simulator.bus, options.server);
}

void plugInHandhelds(const Simulator& simulator) {
    for (const auto& ms1 : simulator.handhelds)
        ms1->plugIn();
    if (!simulator.handhelds.empty())
        out() << "handhelds: " << simulator.handhelds.size() << " MS1 on the bus, logging in" << Qt::endl;
    if (simulator.orcDevices)
        simulator.orcDevices->plugIn();
}

// Stellwerk asks a station's web server for the pictures on port 80 unless the address names another.
void tellStationAddress(const Simulator& simulator, const simapp::SimOptions& options) {
    if (simulator.server->tcpPort() == 0)
        return;
    const QHostAddress listen = options.server.listenAddress;
    const QString host = listen == QHostAddress::Any || listen == QHostAddress::AnyIPv4
                             ? QStringLiteral("127.0.0.1")
                             : listen.toString();
    out() << "station address for Stellwerk (with the pictures): tcp://" << host << ':'
          << simulator.server->tcpPort() << "?http=" << simulator.http->port() << Qt::endl;
}

// The station's web server: the files, the pictures and the accidents.
bool startWebServer(Simulator& simulator, const simapp::SimOptions& options) {
    const sim::SimulatedStation* station = simulator.station.get();
    simulator.http = std::make_unique<sim::HttpConfigServer>(
        [station](std::string_view path) { return station->layout().fileForPath(path); },
        [station](std::string_view name) { return station->layout().pictureFor(name); });
    if (!simulator.http->listen(options.server.listenAddress, options.httpPort)) {
        err() << "stellwerk-sim: HTTP port " << options.httpPort << ": " << simulator.http->errorString()
              << Qt::endl;
        return false;
    }
    out() << "listening: http://" << options.server.listenAddress.toString() << ':' << simulator.http->port()
          << "/config/" << Qt::endl;
    tellStationAddress(simulator, options);
    return true;
}

// Every accident as a line on standard output, and the counts on the web server (GET /accidents).
void reportAccidents(const Simulator& simulator) {
    QObject::connect(simulator.trains.get(), &sim::TrainMovement::accident,
                     [](const sim::Accident& accident) {
                         out() << "accident: " << QString::fromStdString(accident.text) << Qt::endl;
                     });
    if (!simulator.http)
        return;
    const sim::TrainMovement* trains = simulator.trains.get();
    simulator.http->serveJson(
        "/accidents", [trains] { return sim::accidentsJson(trains->accidents(), trains->accidentLog()); });
}

// The trains on the track graph of the station's plan, where --place (or the default) puts them.
bool startTrains(Simulator& simulator, const simapp::SimOptions& options) {
    sim::TrainMovement::Options movement;
    movement.tick = options.tick;
    simulator.trains = std::make_unique<sim::TrainMovement>(*simulator.station,
                                                            std::vector<sim::TrainPlacement>{}, movement);
    reportAccidents(simulator);
    const trackgraph::TrackGraph& graph = simulator.trains->graph();
    for (const sim::TrainPlacement& placement : placementsFor(options, simulator.station->layout(), graph))
        if (const std::optional<std::string> problem = simulator.trains->place(placement)) {
            err() << "stellwerk-sim: --place: " << QString::fromStdString(*problem) << Qt::endl;
            return false;
        }
    simulator.trains->start();
    out() << "trains: " << simulator.trains->trainCount() << " on " << graph.blocks().size() << " blocks"
          << Qt::endl;
    return true;
}

bool start(Simulator& simulator, const simapp::SimOptions& options, sim::StationLayout layout) {
    sim::SimulatedStation::Options stationOptions;
    stationOptions.gleisbox = options.gleisbox;
    stationOptions.handheldMaster = options.handheldMaster;
    simulator.station = std::make_unique<sim::SimulatedStation>(std::move(layout), stationOptions);
    if (options.handhelds > 0 || options.handheldMaster || options.roModules > 0 || options.hasOrcDevices())
        addHandhelds(simulator, options);
    else
        simulator.server = std::make_unique<sim::StationServer>(*simulator.station, options.server);
    QObject::connect(simulator.server.get(), &sim::StationServer::problem,
                     [](const QString& message) { err() << "stellwerk-sim: " << message << Qt::endl; });
    if (!simulator.server->listen()) {
        err() << "stellwerk-sim: " << simulator.server->errorString() << Qt::endl;
        return false;
    }
    for (const QString& listener : simulator.server->listeners())
        out() << "listening: " << listener << Qt::endl;
    plugInHandhelds(simulator);
    if (options.httpPort != 0 && !startWebServer(simulator, options))
        return false;
    return !options.trains || startTrains(simulator, options);
}

} // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName("stellwerk-sim");
    const simapp::ParsedOptions parsed = simapp::parseSimOptions(QCoreApplication::arguments());
    if (!parsed.options) {
        (parsed.error ? err() : out()) << parsed.message << Qt::endl;
        return parsed.error ? 2 : 0;
    }
    std::optional<sim::StationLayout> layout = loadLayout(*parsed.options);
    if (!layout)
        return 1;
    Simulator simulator;
    if (!start(simulator, *parsed.options, std::move(*layout)))
        return 1;
    simapp::ShutdownSignal shutdown;
    QObject::connect(&shutdown, &simapp::ShutdownSignal::requested, &app, [] {
        out() << "stopping" << Qt::endl;
        QCoreApplication::quit();
    });
    out() << "press Ctrl-C to stop" << Qt::endl;
    return QCoreApplication::exec();
}
