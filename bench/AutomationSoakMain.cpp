// stellwerk-automation-soak: automatic operation for a long time, with the station going away. Three trains
// on the demo (the BR 218 and the ICE on loop schedules, the V 100 wherever it finds room) driven by the
// automation over loopback TCP against the simulated CS2, whose trains move on the simulated clock (50 ms
// steps, as tests/e2e/AutomationRig.h runs them); every N simulated minutes the station's server is killed,
// the app notices the silence, the server comes back, the station is read again and the automation resumed.
// Prints the accidents (the simulator's referee; must be 0), block moves, the worst dwell error, faults,
// resident memory at start and end. Then the latency: an unknown occupant appears (an S88 event leaves the
// station) in the block a running train is bound for, and the time until its stop command arrives at the
// station is taken, over --trials trials (median, p99; target p99 < 20 ms). Not part of ctest; see
// docs/soak.md. Exit 0 when there was no accident and at least 100 block moves.
//
//   build/bench/stellwerk-automation-soak [--minutes 60] [--restart-every 10] [--trials 200]

#include "automation/Automation.h"
#include "automation/Schedule.h"
#include "cs2/Codec.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "sim/TrainMovement.h"
#include "sim/TrainPlacement.h"
#include "station/StartupSequence.h"
#include "station/StationSession.h"
#include "transport/TransportFactory.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <memory>
#include <unistd.h>
#include <vector>

namespace stellwerk::soak {
namespace {

using namespace std::chrono_literals;

constexpr std::chrono::milliseconds Step{50};

double residentMiB() {
    QFile statm(QStringLiteral("/proc/self/statm"));
    if (!statm.open(QIODevice::ReadOnly))
        return 0;
    const QList<QByteArray> fields = statm.readAll().split(' ');
    return fields.size() > 1 ? fields[1].toDouble() * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0) : 0;
}

// Runs the event loop until the condition holds (true) or the time is up (false).
bool waitFor(const std::function<bool()>& condition, int timeoutMs = 10000) {
    QElapsedTimer clock;
    clock.start();
    QTimer tick;
    tick.start(10);
    while (!condition()) {
        if (clock.elapsed() >= timeoutMs)
            return condition();
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    }
    return true;
}

constexpr const char* Schedules = R"({"trains": [
    {"loc": "mfx:1", "loop": true,
     "stops": [{"block": "Gleis 1", "dwell": 8}, {"block": "Block 3", "dwell": 5}]},
    {"loc": "mfx:2", "loop": true,
     "stops": [{"block": "Block 1", "dwell": 4}, {"block": "Gleis 2", "dwell": 6}]}]})";

// The station with its moving trains behind a TCP server on a fixed loopback port; the app's session,
// railway and automation on the graph of the station's own plan.
class SoakRig {
public:
    SoakRig() : station_(sim::StationLayout::demo()), movement_(station_, sim::demoPlacements()) {
        movement_.start();
        movement_.stop(); // the soak runs its clock
        QObject::connect(&movement_, &sim::TrainMovement::accident,
                         [this](const sim::Accident& accident) { accidents_.push_back(accident.text); });
        QObject::connect(&station_, &sim::SimulatedStation::frameReceived,
                         [this](const can::CanFrame& frame) { received(frame); });
    }
    ~SoakRig() {
        automation_.reset();
        railway_.reset();
        startup_.reset();
        session_.reset();
        bus_.reset();
        transport_.reset();
        server_.reset();
    }

    bool start() {
        if (!startServer())
            return false;
        transport_ = transport::createTransport(transport::TcpSettings{
            QStringLiteral("127.0.0.1"), port_, transport::ReconnectTiming{20ms, 100ms, 1000ms}});
        bus_ = std::make_unique<bus::Bus>(*transport_, busreading::BusProfile::centralStation());
        station::StationSettings settings;
        settings.uid = 0x53574B02;
        settings.commands = {500ms, 3};
        session_ = std::make_unique<station::StationSession>(*bus_, settings);
        railway_ = std::make_unique<model::Railway>(*session_);
        QObject::connect(railway_.get(), &model::Railway::locomotiveCommandSent, [this] { ++inFlight_; });
        QObject::connect(railway_.get(), &model::Railway::locomotiveCommandAcknowledged,
                         [this] { --inFlight_; });
        QObject::connect(railway_.get(), &model::Railway::locomotiveCommandFailed, [this] { --inFlight_; });
        transport_->open();
        if (!waitFor([&] { return transport_->state() == transport::Transport::State::Connected; }) ||
            !readStation())
            return false;
        railway_->go();
        if (!waitFor([&] { return railway_->power() == station::PowerState::Running; }))
            return false;
        layout_.useStationDownload(startup_->result());
        graph_ = layout_.graph();
        automation::Dispatcher::Options options;
        options.dwell = 1000;
        automation_ = std::make_unique<automation::Automation>(*railway_, *graph_, options);
        automation_->setClock([this] { return now_; });
        QObject::connect(automation_.get(), &automation::Automation::happened,
                         [this](const automation::AutomationEvent& event) {
                             using Kind = automation::AutomationEvent::Kind;
                             if (event.kind == Kind::Fault || event.kind == Kind::Lost ||
                                 event.kind == Kind::Overrun)
                                 faults_.push_back(std::to_string(now_ / 1000) + " s: " + event.text);
                         });
        for (const sim::TrainPlacement& placement : sim::demoPlacements())
            if (automation_->place(placement.locId, placement.contact, placement.towards))
                return false;
        const auto schedules = automation::parseSchedules(Schedules);
        if (!schedules)
            return false;
        for (const auto& [locId, schedule] : *schedules)
            if (automation_->setSchedule(locId, schedule))
                return false;
        automation_->start(0ms);
        return settle();
    }

    // Simulated time: the trains move a step, the app hears it and answers, then the automation's clock.
    void run(std::chrono::milliseconds duration) {
        for (auto elapsed = 0ms; elapsed < duration; elapsed += Step) {
            movement_.advance(Step);
            now_ += Step.count();
            settle();
            automation_->tick();
            settle();
        }
    }

    // The station's server killed and started again on the same port; the app reads it again and the
    // automation is resumed (which stops every train first).
    bool restartStation() {
        server_.reset();
        if (!waitFor([&] { return !railway_->isStateReported(); }, 30000) || !startServer() ||
            !waitFor([&] { return transport_->state() == transport::Transport::State::Connected; }) ||
            !readStation())
            return false;
        automation_->resume();
        return settle();
    }

    int accidents() const { return movement_.accidents().total(); }
    const std::vector<std::string>& accidentLog() const { return accidents_; }
    const std::vector<std::string>& faultLog() const { return faults_; }
    const automation::Dispatcher& dispatcher() const { return automation_->dispatcher(); }

    // One latency trial: once a train runs towards a destination beyond the next block, an unknown occupant
    // appears there (an S88 event leaves the station); the time until the station receives the train's
    // stop. Then the contact is freed and the automation resumed. Nanoseconds; -1 when none was seen.
    qint64 latencyTrial() {
        std::optional<std::pair<std::uint32_t, int>> running;
        for (int i = 0; i < 2000 && !(running = runningTowardsFarBlock()); ++i)
            run(Step);
        if (!running)
            return -1;
        const trackgraph::ContactKey ghost = graph_->block(running->second).contacts.front().contact;
        const auto device = std::uint16_t(ghost.device), number = std::uint16_t(ghost.number);
        stopping_ = running->first;
        stopNs_ = -1;
        trialClock_.start();
        station_.setContact(device, number, true);
        waitFor([&] { return stopNs_ >= 0; }, 2000);
        stopping_ = 0;
        station_.setContact(device, number, false);
        settle();
        automation_->resume();
        settle();
        return stopNs_;
    }

private:
    // An automatic train running to a destination that is not right ahead of it, whose contacts are free.
    std::optional<std::pair<std::uint32_t, int>> runningTowardsFarBlock() const {
        const automation::Dispatcher& dispatcher = automation_->dispatcher();
        for (const auto& [locId, train] : dispatcher.trains()) {
            const automation::TrainBody* body = dispatcher.tracking().body(locId);
            if (train.state != automation::TrainState::Running || !train.destination || !body ||
                graph_->block(*train.destination).contacts.empty() ||
                dispatcher.tracking().blockOccupied(*train.destination))
                continue;
            bool next = false;
            for (const int id : graph_->connectionsFrom({body->frontBlock, body->towards}))
                next = next || graph_->connection(id).to.block == *train.destination;
            if (!next && body->frontBlock != *train.destination)
                return std::pair{locId, *train.destination};
        }
        return std::nullopt;
    }

    bool startServer() {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.udp = false;
        settings.tcpPort = port_;
        server_ = std::make_unique<sim::StationServer>(station_, settings);
        if (!server_->listen())
            return false;
        port_ = server_->tcpPort();
        return true;
    }

    bool readStation() {
        station::StartupOptions options;
        options.readStatusData = false;
        startup_ = std::make_unique<station::StartupSequence>(*session_, options);
        bool ready = false;
        QObject::connect(startup_.get(), &station::StartupSequence::ready,
                         [&](const station::StartupResult& result) {
                             railway_->load(result);
                             ready = true;
                         });
        startup_->start();
        return waitFor([&] { return ready; }, 20000);
    }

    // Until every command was answered and the railway shows every contact as the station has it.
    bool settle() {
        return waitFor([&] {
            if (inFlight_ > 0 || automation_->switchingsInFlight() > 0)
                return false;
            for (const trackgraph::Block& block : graph_->blocks())
                for (const trackgraph::ContactOnBlock& on : block.contacts) {
                    const auto device = std::uint16_t(on.contact.device),
                               number = std::uint16_t(on.contact.number);
                    const model::FeedbackContact* contact =
                        railway_->contact(model::contactKey(device, number));
                    if ((contact && contact->known() && contact->occupied()) !=
                        station_.contact(device, number))
                        return false;
                }
            return true;
        });
    }

    void received(const can::CanFrame& frame) {
        const cs2::DecodeResult decoded = cs2::decode(frame);
        const auto* speed = decoded ? std::get_if<cs2::LocoSpeed>(&decoded->body) : nullptr;
        if (stopping_ != 0 && speed && speed->loco.value() == stopping_ && speed->speed == 0 && stopNs_ < 0)
            stopNs_ = trialClock_.nsecsElapsed();
    }

    sim::SimulatedStation station_;
    sim::TrainMovement movement_;
    std::unique_ptr<sim::StationServer> server_;
    std::uint16_t port_ = 0;
    std::unique_ptr<transport::Transport> transport_;
    std::unique_ptr<bus::Bus> bus_;
    std::unique_ptr<station::StationSession> session_;
    std::unique_ptr<model::Railway> railway_;
    std::unique_ptr<station::StartupSequence> startup_;
    model::LayoutInUse layout_;
    std::shared_ptr<const trackgraph::TrackGraph> graph_;
    std::unique_ptr<automation::Automation> automation_;
    automation::Millis now_ = 0;
    int inFlight_ = 0;
    std::vector<std::string> accidents_;
    std::vector<std::string> faults_;
    QElapsedTimer trialClock_;
    std::uint32_t stopping_ = 0; // the train a trial waits to see stopped
    qint64 stopNs_ = -1;
};

double percentileMs(std::vector<qint64> values, double fraction) {
    if (values.empty())
        return 0;
    std::sort(values.begin(), values.end());
    const auto index = std::size_t(fraction * double(values.size() - 1) + 0.5);
    return double(values[std::min(values.size() - 1, index)]) / 1e6;
}

int run(int minutes, int restartEvery, int trials) {
    SoakRig rig;
    const double rssStart = residentMiB();
    if (!rig.start()) {
        std::fprintf(stderr, "the station could not be read or the trains not placed\n");
        return 1;
    }
    QElapsedTimer wall;
    wall.start();
    int restarts = 0;
    for (int minute = 0; minute < minutes; ++minute) {
        if (minute > 0 && restartEvery > 0 && minute % restartEvery == 0) {
            if (!rig.restartStation()) {
                std::fprintf(stderr, "the station did not come back after restart %d\n", restarts + 1);
                return 1;
            }
            ++restarts;
        }
        rig.run(std::chrono::minutes(1));
    }
    const automation::Dispatcher& dispatcher = rig.dispatcher();
    std::printf("simulated minutes       %d (%.1f s of wall time)\n", minutes, double(wall.elapsed()) / 1000);
    std::printf("station restarts        %d\n", restarts);
    std::printf("accidents               %d (must be 0)\n", rig.accidents());
    for (const std::string& accident : rig.accidentLog())
        std::printf("  %s\n", accident.c_str());
    std::printf("block moves             %d (at least 100)\n", dispatcher.blockMoves());
    std::printf("faults                  %d\n", dispatcher.faults());
    for (const std::string& fault : rig.faultLog())
        std::printf("  %s\n", fault.c_str());
    std::printf("worst dwell error       %lld ms (at most 1000)\n",
                static_cast<long long>(dispatcher.worstDwellError()));
    std::printf("memory                  %.1f MiB at start, %.1f MiB at end\n", rssStart, residentMiB());
    const bool passed = rig.accidents() == 0 && dispatcher.blockMoves() >= 100;
    std::vector<qint64> latencies;
    for (int trial = 0; trial < trials; ++trial)
        if (const qint64 ns = rig.latencyTrial(); ns >= 0)
            latencies.push_back(ns);
    std::printf("S88 to drive command    %zu of %d trials, median %.2f ms, p99 %.2f ms, worst %.2f ms "
                "(target p99 < 20 ms)\n",
                latencies.size(), trials, percentileMs(latencies, 0.5), percentileMs(latencies, 0.99),
                percentileMs(latencies, 1.0));
    std::printf("accidents after trials  %d\n", rig.accidents());
    return passed && rig.accidents() == 0 ? 0 : 1;
}

} // namespace
} // namespace stellwerk::soak

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Automatic operation on the simulated demo for a long time."));
    parser.addHelpOption();
    parser.addOption({QStringLiteral("minutes"), QStringLiteral("Simulated minutes (60)."),
                      QStringLiteral("n"), QStringLiteral("60")});
    parser.addOption({QStringLiteral("restart-every"),
                      QStringLiteral("Restart the station every n simulated minutes (10; 0: never)."),
                      QStringLiteral("n"), QStringLiteral("10")});
    parser.addOption({QStringLiteral("trials"), QStringLiteral("Latency trials after the soak (200)."),
                      QStringLiteral("n"), QStringLiteral("200")});
    parser.process(app);
    return stellwerk::soak::run(parser.value(QStringLiteral("minutes")).toInt(),
                                parser.value(QStringLiteral("restart-every")).toInt(),
                                parser.value(QStringLiteral("trials")).toInt());
}
