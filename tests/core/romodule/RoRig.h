#pragma once

#include "EventLoopWait.h"
#include "bus/Bus.h"
#include "romodule/RoModuleSession.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedRoModule.h"
#include "transport/LoopbackTransport.h"

#include <memory>
#include <vector>

namespace stellwerk::romodule::test {

// A station's bus with one simulated RO module on it, reached by Stellwerk through a real (loopback)
// transport: the module is a peer of a SimulatedBus whose outside is the far end of the loopback, and the
// session sits on a bus::Bus over the near end. Records what the session confirmed and what failed.
struct RoRig {
    explicit RoRig(SessionTiming timing = quickTiming(),
                   ro::RoProfile roProfile = ro::RoProfile::simulator(1))
        : profile(std::move(roProfile)), module(profile) {
        transport::LoopbackTransport::join(appEnd, busEnd);
        simulatedBus.attach(module);
        QObject::connect(
            &busEnd, &transport::Transport::framesReceived, &simulatedBus,
            [this](const std::vector<can::CanFrame>& frames) { simulatedBus.putFromOutside(frames); });
        QObject::connect(&simulatedBus, &sim::SimulatedBus::framesCarried, &busEnd,
                         [this](const std::vector<can::CanFrame>& frames) { busEnd.sendBatch(frames); });
        busreading::BusProfile busProfile = busreading::BusProfile::centralStation();
        busProfile.addRoModule(profile.ids);
        bus = std::make_unique<bus::Bus>(appEnd, busProfile, QStringLiteral("CS2"));
        session = std::make_unique<RoModuleSession>(*bus, profile, timing);
        QObject::connect(session.get(), &RoModuleSession::outputsFailed, session.get(),
                         [this](std::uint32_t relays, const QString&) { failed |= relays; });
        QObject::connect(session.get(), &RoModuleSession::inputsChanged, session.get(),
                         [this](std::uint32_t, std::uint32_t changed) { changedSeen |= changed; });
        appEnd.open();
        busEnd.open();
    }

    // Fast answers, polling rare enough that a test knows which request a fault hits.
    static SessionTiming quickTiming() {
        SessionTiming timing;
        timing.answerTimeout = std::chrono::milliseconds(100);
        timing.pollPeriod = std::chrono::milliseconds(60000);
        timing.firstJob = 0x34;
        return timing;
    }

    bool waitFor(const std::function<bool()>& condition, int ms = 3000) {
        return support::runEventsUntil(condition, ms);
    }
    // Started, relays read and the first poll done.
    bool started() {
        session->start();
        return waitFor([this] { return session->idle() && session->outputs().has_value(); });
    }
    // The writes the module carried out on its relay word.
    std::vector<std::uint32_t> relayWrites() const {
        std::vector<std::uint32_t> values;
        for (const auto& write : module.writes())
            if (write.address == profile.outputs.address)
                values.push_back(write.value);
        return values;
    }

    ro::RoProfile profile;
    sim::SimulatedBus simulatedBus;
    sim::SimulatedRoModule module;
    transport::LoopbackTransport appEnd{QStringLiteral("stellwerk")};
    transport::LoopbackTransport busEnd{QStringLiteral("ro-bus")};
    std::unique_ptr<bus::Bus> bus;
    std::unique_ptr<RoModuleSession> session;
    std::uint32_t failed = 0;      // relays whose change the session reported as failed
    std::uint32_t changedSeen = 0; // inputs reported with their change flag
};

} // namespace stellwerk::romodule::test
