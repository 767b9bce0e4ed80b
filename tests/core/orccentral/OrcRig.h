#pragma once

// The OpenRailCAN central on one end of a loopback transport; on the other end a simulated bus with the
// simulated devices as peers (a booster, an 8-output decoder, a 32-input encoder). Everything that reaches
// the devices' side of the wire is kept, in order, as the frames' document notation.

#include "EventLoopWait.h"
#include "bus/Bus.h"
#include "can/FrameText.h"
#include "orccentral/OrcSession.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedOrcDevices.h"
#include "transport/LoopbackTransport.h"

#include <QObject>
#include <algorithm>
#include <functional>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace stellwerk::orccentral::test {

inline constexpr int WaitMs = 5000;

inline bool waitFor(const std::function<bool()>& condition, int timeoutMs = WaitMs) {
    return support::runEventsUntil(condition, timeoutMs);
}

inline constexpr std::uint32_t BoosterUid = 0x3A2E0042;
inline constexpr std::uint32_t DecoderUid = 0x3A2E2E01;
inline constexpr std::uint32_t EncoderUid = 0x3A2E2E10;
inline constexpr std::uint32_t TwinUid = 0x11112E01; // same low 16 bits as the decoder

inline OrcSession::Settings fastSettings(std::chrono::milliseconds pingPeriod = std::chrono::seconds(60)) {
    OrcSession::Settings settings;
    settings.timing.pingPeriod = pingPeriod;
    // Longer than the document-less default of 250 ms, so that a loaded machine does not turn an ack that
    // comes late into "sent, unconfirmed".
    settings.timing.answerTimeout = std::chrono::milliseconds(1000);
    settings.reservedBusIds = {0x3005}; // MM2 turnout 5 of the layout
    return settings;
}

// Another program on the bus (a throttle, another central, a CS2, garbage): a peer on the simulated bus, so
// that its frames reach the simulated devices and, through the transport, the central.
class OtherProgram : public QObject {
    Q_OBJECT

public:
    void receive(const can::CanFrame&) {}
    void say(std::string_view text) { emit framesEmitted({can::parseFrame(text)->frame}); }

signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);
};

class OrcRig {
public:
    explicit OrcRig(OrcSession::Settings settings = fastSettings(), bool decoderAcks = true)
        : decoder(DecoderUid, decoderAcks), session(bus, std::move(settings)) {
        transport::LoopbackTransport::join(central, devices);
        QObject::connect(&devices, &transport::Transport::framesReceived, &simBus,
                         [this](const std::vector<can::CanFrame>& frames) {
                             for (const can::CanFrame& f : frames)
                                 wire.push_back(can::formatDocument(f));
                             simBus.putFromOutside(frames);
                         });
        QObject::connect(&simBus, &sim::SimulatedBus::framesCarried, &devices,
                         [this](const std::vector<can::CanFrame>& frames) { devices.sendBatch(frames); });
        simBus.attach(booster);
        simBus.attach(decoder);
        simBus.attach(encoder);
        simBus.attach(other);
        central.open();
        devices.open();
    }

    // Plugs the devices in and starts the central; true when all are online.
    bool started(std::initializer_list<sim::SimulatedOrcDevice*> peers = {}) {
        booster.plugIn();
        decoder.plugIn();
        encoder.plugIn();
        for (sim::SimulatedOrcDevice* peer : peers)
            peer->plugIn();
        session.start();
        return waitFor([&] { return onlineCount() == 3 + peers.size(); });
    }

    std::size_t onlineCount() const {
        return std::size_t(std::ranges::count_if(
            session.devices(), [](const OrcDevice& d) { return d.state == OrcDevice::State::Online; }));
    }
    OrcDevice::State state(std::uint32_t uid) const {
        const OrcDevice* d = session.device(uid);
        return d ? d->state : OrcDevice::State::Unassigned;
    }
    // How often the frame (document notation) reached the devices' side.
    std::size_t onWire(const std::string& frame) const {
        return std::size_t(std::ranges::count(wire, frame));
    }
    // A frame of another program on the bus: the devices and the central receive it.
    void fromOtherProgram(std::string_view text) { other.say(text); }

    transport::LoopbackTransport central{QStringLiteral("central")};
    transport::LoopbackTransport devices{QStringLiteral("devices")};
    bus::Bus bus{central, busreading::BusProfile::openRailCan(), QStringLiteral("ORC")};
    sim::SimulatedBus simBus;
    sim::SimulatedOrcBooster booster{BoosterUid};
    sim::SimulatedOrcDecoder decoder;
    sim::SimulatedOrcEncoder encoder{EncoderUid};
    OtherProgram other;
    OrcSession session;
    std::vector<std::string> wire;
};

} // namespace stellwerk::orccentral::test
