#pragma once

// The railway of ModelBench with a device bus beside the station: one simulated RO module, an ORC decoder
// (8 outputs, acknowledging or not) and an ORC encoder on a SimulatedBus behind a loopback pair, the real
// OpenRailCAN central and RO module session on the app's end, and RailwayDevices binding them into the
// railway: W1 (accessory 1) to relay 1, S5 (accessory 5) to decoder output 2, the plan's contact 7 to
// encoder input 3 and contact 8 to the module's input 2.

#include "ModelBench.h"
#include "model/RailwayDevices.h"
#include "orccentral/OrcSession.h"
#include "romodule/RoModuleSession.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedOrcDevices.h"
#include "sim/SimulatedRoModule.h"

#include <memory>

namespace stellwerk::model::test {

inline constexpr std::uint32_t DecoderUid = 0x3A2E0011;
inline constexpr std::uint32_t EncoderUid = 0x3A2E0012;
inline constexpr std::uint16_t DecoderBusId = 0x0011; // the low 16 bits of its UID, which is free
inline const QString ModuleName = QStringLiteral("RO 1");
inline constexpr ContactKey EncoderContact = contactKey(0, 7);
inline constexpr ContactKey ModuleContact = contactKey(0, 8);

inline DeviceBindings benchBindings() {
    DeviceBindings bindings;
    bindings.accessories.push_back({1, RoRelay{ModuleName, 1}});
    bindings.accessories.push_back({5, OrcOutput{DecoderBusId, 2}});
    bindings.contacts.push_back({EncoderContact, OrcInput{EncoderUid, 3}});
    bindings.contacts.push_back({ModuleContact, RoInput{ModuleName, 2}});
    return bindings;
}

class DeviceBench {
public:
    explicit DeviceBench(bool decoderAcknowledges = true) : decoder(DecoderUid, decoderAcknowledges) {
        transport::LoopbackTransport::join(busEnd, appEnd);
        simulatedBus.attach(module);
        simulatedBus.attach(decoder);
        simulatedBus.attach(encoder);
        QObject::connect(
            &busEnd, &transport::Transport::framesReceived, &simulatedBus,
            [this](const std::vector<can::CanFrame>& frames) { simulatedBus.putFromOutside(frames); });
        QObject::connect(&simulatedBus, &sim::SimulatedBus::framesCarried, &busEnd,
                         [this](const std::vector<can::CanFrame>& frames) { busEnd.sendBatch(frames); });
        QObject::connect(&appEnd, &transport::Transport::framesSent, &busEnd,
                         [this](const std::vector<can::CanFrame>& frames) {
                             sent.insert(sent.end(), frames.begin(), frames.end());
                         });
        busEnd.open();
        appEnd.open();
    }

    // The station's start-up, then the device sessions started and every device found.
    bool start() {
        if (!railway.start())
            return false;
        decoder.plugIn();
        encoder.plugIn();
        orc->start();
        roModule->start();
        devices.setSessions(orc.get(), {roModule.get()});
        return waitFor([this] {
            const auto* found = orc->device(DecoderUid);
            return found && found->state == orccentral::OrcDevice::State::Online && orc->device(EncoderUid) &&
                   roModule->state() == romodule::RoModuleSession::State::Online && roModule->inputs();
        });
    }

    static orccentral::OrcSession::Settings orcSettings() {
        orccentral::OrcSession::Settings settings;
        settings.timing.pingPeriod = 100ms;
        settings.timing.answerTimeout = 100ms;
        return settings;
    }
    static romodule::SessionTiming roTiming() {
        romodule::SessionTiming timing;
        timing.answerTimeout = 50ms;
        timing.pollPeriod = 50ms;
        return timing;
    }
    static busreading::BusProfile deviceBusProfile() {
        busreading::BusProfile profile{busreading::Protocol::Orc};
        profile.addRoModule(ro::RoProfile::simulator(1).ids);
        return profile;
    }
    static ro::RoProfile moduleProfile() {
        ro::RoProfile profile = ro::RoProfile::simulator(1);
        profile.name = ModuleName.toStdString();
        return profile;
    }

    ModelBench railway;
    sim::SimulatedBus simulatedBus;
    sim::SimulatedRoModule module{moduleProfile()};
    sim::SimulatedOrcDecoder decoder;
    sim::SimulatedOrcEncoder encoder{EncoderUid};
    transport::LoopbackTransport busEnd{QStringLiteral("device bus")};
    transport::LoopbackTransport appEnd{QStringLiteral("app's device bus")};
    bus::Bus deviceBus{appEnd, deviceBusProfile(), QStringLiteral("devices")};
    std::unique_ptr<orccentral::OrcSession> orc =
        std::make_unique<orccentral::OrcSession>(deviceBus, orcSettings());
    std::unique_ptr<romodule::RoModuleSession> roModule =
        std::make_unique<romodule::RoModuleSession>(deviceBus, moduleProfile(), roTiming());
    RailwayDevices devices{railway.railway, benchBindings()};
    std::vector<can::CanFrame> sent; // what the app put on the device bus
};

} // namespace stellwerk::model::test
