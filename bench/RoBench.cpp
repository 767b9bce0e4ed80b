// RO relay/IO modules on one CAN bus:
//   1. how many modules one 250 kbit/s bus can poll at 10 Hz (a read request and its answer per poll),
//      computed from the frame sizes with no and with worst-case bit stuffing, for 29- and 11-bit ids;
//   2. the check against the simulated bus: that many simulated modules polled by Stellwerk's sessions at
//      10 Hz for a few seconds, the frames the bus carried counted and their bits (stuff bits counted
//      exactly) added up, and each module's poll rate measured;
//   3. the request round trip of one module over a loopback transport (session -> transport -> simulated
//      bus -> module -> back): median and p99.
// A plain harness printing figures. Run: build/bench/stellwerk-ro-bench [seconds]

#include "CanBitTiming.h"
#include "bus/Bus.h"
#include "romodule/RoModuleSession.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedRoModule.h"
#include "transport/LoopbackTransport.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

using namespace stellwerk;

namespace {

constexpr double BusBitsPerSecond = 250000;
constexpr double PollHz = 10;
constexpr unsigned AnswerBytes = 7; // 004 §3.5

// Modules the bus carries at full load when each poll costs `bits`.
int modulesFor(double bitsPerPoll) {
    return int(BusBitsPerSecond / (bitsPerPoll * PollHz));
}

int printCapacity() {
    std::printf(
        "1. Modules one 250 kbit/s bus polls at %.0f Hz (one read request + one 7-byte answer a poll)\n",
        PollHz);
    std::printf("   %-22s %9s %9s %11s %11s\n", "ids, read request", "bits/poll", "(worst)", "modules",
                "(worst)");
    int worstExtended = 0;
    for (const bool extended : {true, false})
        for (const unsigned requestBytes : {8u, 4u}) {
            const unsigned nominal =
                bench::nominalBits(extended, requestBytes) + bench::nominalBits(extended, AnswerBytes);
            const unsigned worst =
                bench::worstCaseBits(extended, requestBytes) + bench::worstCaseBits(extended, AnswerBytes);
            std::printf("   %-6s %-15s %9u %9u %11d %11d\n", extended ? "29-bit" : "11-bit",
                        requestBytes == 8 ? "8 bytes" : "4 bytes", nominal, worst, modulesFor(nominal),
                        modulesFor(worst));
            if (extended && requestBytes == 8)
                worstExtended = modulesFor(worst);
        }
    std::printf("   (the bus alone: a CS2's own traffic on the same bus takes its share first)\n\n");
    return worstExtended;
}

// Modules on a simulated bus, reached through a loopback transport, each with its own session.
struct SimulatedRoBus {
    sim::SimulatedBus bus;
    transport::LoopbackTransport appEnd{QStringLiteral("stellwerk")}, busEnd{QStringLiteral("ro-bus")};
    std::vector<std::unique_ptr<sim::SimulatedRoModule>> modules;
    std::unique_ptr<bus::Bus> appBus;
    std::vector<std::unique_ptr<romodule::RoModuleSession>> sessions;

    SimulatedRoBus(int count, std::chrono::milliseconds pollPeriod) {
        transport::LoopbackTransport::join(appEnd, busEnd);
        QObject::connect(&busEnd, &transport::Transport::framesReceived, &bus,
                         [this](const std::vector<can::CanFrame>& frames) { bus.putFromOutside(frames); });
        QObject::connect(&bus, &sim::SimulatedBus::framesCarried, &busEnd,
                         [this](const std::vector<can::CanFrame>& frames) { busEnd.sendBatch(frames); });
        busreading::BusProfile profile = busreading::BusProfile::centralStation();
        for (int n = 1; n <= count; ++n)
            profile.addRoModule(ro::RoProfile::simulator(std::uint16_t(n)).ids);
        appBus = std::make_unique<bus::Bus>(appEnd, profile, QStringLiteral("CS2"));
        romodule::SessionTiming timing;
        timing.pollPeriod = pollPeriod;
        for (int n = 1; n <= count; ++n) {
            const ro::RoProfile module = ro::RoProfile::simulator(std::uint16_t(n));
            bus.attach(*modules.emplace_back(std::make_unique<sim::SimulatedRoModule>(module)));
            sessions.push_back(std::make_unique<romodule::RoModuleSession>(*appBus, module, timing));
        }
        appEnd.open();
        busEnd.open();
    }
};

void runFor(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

void checkAgainstTheSimulatedBus(int modules, int seconds) {
    SimulatedRoBus rig(modules, std::chrono::milliseconds(int(1000 / PollHz)));
    std::uint64_t frames = 0, bits = 0;
    unsigned maxBits = 0;
    QObject::connect(rig.appBus.get(), &bus::Bus::framesSeen, rig.appBus.get(),
                     [&](const std::vector<can::CanFrame>& seen, bool) {
                         for (const can::CanFrame& frame : seen) {
                             const unsigned b = bench::exactBits(frame);
                             ++frames, bits += b, maxBits = std::max(maxBits, b);
                         }
                     });
    for (auto& session : rig.sessions)
        session->start();
    runFor(1000); // start-up: relays read, first polls
    const std::uint64_t framesBefore = frames, bitsBefore = bits;
    std::vector<std::uint64_t> okBefore;
    for (const auto& session : rig.sessions)
        okBefore.push_back(session->counters().ok);
    QElapsedTimer clock;
    clock.start();
    runFor(seconds * 1000);
    const double elapsed = double(clock.elapsed()) / 1000.0;
    double slowest = 1e9;
    std::uint64_t timeouts = 0;
    for (std::size_t i = 0; i < rig.sessions.size(); ++i) {
        slowest = std::min(slowest, double(rig.sessions[i]->counters().ok - okBefore[i]) / elapsed);
        timeouts += rig.sessions[i]->counters().timeouts;
    }
    const double framesPerSecond = double(frames - framesBefore) / elapsed;
    const double bitsPerSecond = double(bits - bitsBefore) / elapsed;
    std::printf("2. Checked on the simulated bus: %d modules polled at %.0f Hz for %.1f s\n", modules, PollHz,
                elapsed);
    std::printf("   frames carried: %.0f/s (model: %.0f/s), slowest module: %.1f polls/s, timeouts: %llu\n",
                framesPerSecond, 2 * PollHz * modules, slowest, static_cast<unsigned long long>(timeouts));
    std::printf("   bits with exact stuffing: %.0f/s = %.1f %% of 250 kbit/s (longest frame %u bits, worst "
                "case %u)\n\n",
                bitsPerSecond, 100 * bitsPerSecond / BusBitsPerSecond, maxBits,
                bench::worstCaseBits(true, 8));
}

void roundTrip(int requests) {
    SimulatedRoBus rig(1, std::chrono::milliseconds(3600 * 1000));
    romodule::RoModuleSession& session = *rig.sessions.front();
    session.start();
    while (!session.idle() || !session.outputs())
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    std::vector<double> micros;
    QElapsedTimer clock;
    QObject::connect(&session, &romodule::RoModuleSession::requestFinished, &session, [&] {
        micros.push_back(double(clock.nsecsElapsed()) / 1000.0);
        if (int(micros.size()) < requests) {
            clock.start();
            session.read(0x0020, ro::Width::Word);
        }
    });
    clock.start();
    session.read(0x0020, ro::Width::Word);
    while (int(micros.size()) < requests)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    std::sort(micros.begin(), micros.end());
    std::printf("3. Request round trip over a loopback transport (%d reads, one at a time)\n", requests);
    std::printf("   median %.0f us, p99 %.0f us, max %.0f us\n", micros[micros.size() / 2],
                micros[micros.size() * 99 / 100], micros.back());
}

} // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    const int seconds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    const int modules = printCapacity();
    checkAgainstTheSimulatedBus(modules, seconds);
    roundTrip(2000);
    return 0;
}
