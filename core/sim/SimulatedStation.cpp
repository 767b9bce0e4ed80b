#include "sim/SimulatedStation.h"

#include "cs2/Codec.h"
#include "cs2/Hash.h"
#include "mcan/Codec.h"
#include "sim/AccessoryCommands.h"
#include "sim/ConfigDataService.h"
#include "sim/DeviceService.h"
#include "sim/FeedbackService.h"
#include "sim/LocoCommands.h"
#include "sim/MemoryFunctions.h"
#include "sim/MfxRegistry.h"
#include "sim/SystemCommands.h"

#include <QTimer>
#include <algorithm>

namespace stellwerk::sim {
namespace {

StationIdentity identityFrom(const SimulatedStation::Options& options) {
    StationIdentity identity;
    identity.uid = options.uid;
    if (options.gleisbox)
        identity.gleisboxUid = options.gleisboxUid;
    identity.hash = options.hash ? options.hash : cs2::hashFromUid(options.uid);
    identity.deviceType = options.handheldMaster ? DeviceService::MasterType : DeviceService::GleisboxType;
    return identity;
}

// The layout's locomotives as the station restores them at start: in the cycle, with the speed,
// direction and functions lokomotive.cs2 saved.
void restoreLocomotives(const StationLayout& layout, StationState& state) {
    for (const cs2config::Locomotive& loco : layout.locomotives().locomotives) {
        if (loco.uid == 0 || loco.uid > 0xFFFF)
            continue;
        SimulatedLoco& simulated = state.loco(loco.uid);
        simulated.inCycle = true;
        simulated.speed = std::uint16_t(std::clamp(loco.velocity, 0, 1023));
        simulated.direction = loco.direction == cs2config::TravelDirection::Backward ? 2 : 1;
        for (const cs2config::Function& function : loco.functions)
            if (function.number >= 0 && function.number < int(simulated.functions.size()))
                simulated.functions[std::size_t(function.number)] = function.value ? 1 : 0;
    }
}

} // namespace

// The state and the handlers of the command groups, in the order the dispatcher asks them.
class SimulatedStation::Private {
public:
    Private(StationLayout stationLayout, const Options& options, MemoryFunctions::Later later)
        : layout(std::move(stationLayout)), identity(identityFrom(options)), hashGuard(options.uid),
          system(state, identity), locos(state), mfx(layout, state, options.newMfxDecoders),
          programming(layout, state, mfx), accessories(layout, state), feedback(state, identity),
          devices(state, identity), configData(layout, state), memory(layout, state, std::move(later)) {
        state.power = options.power;
        restoreLocomotives(layout, state);
    }

    void dispatch(const cs2::Message& message, Outbox& out) {
        system.handle(message, out) || locos.handle(message, out) || mfx.handle(message, out) ||
            programming.handle(message, out) || accessories.handle(message, out) ||
            feedback.handle(message, out) || devices.handle(message, out) ||
            configData.handle(message, out) || memory.handle(message, out);
        devices.watchLoad(out); // GO onto a track that draws too much, or a lower limit
    }

    // 1.2.4: another sender with our hash makes us choose a new one nobody uses.
    void watchHash(const can::CanFrame& frame) {
        hashGuard.observe(frame); // remembers every hash in use
        if (cs2::hash(frame) == identity.hash && !cs2::isResponse(frame) &&
            !cs2::hashIsStreamPosition(frame)) {
            std::uint16_t fresh = hashGuard.chooseNewHash();
            while (fresh == identity.hash)
                fresh = hashGuard.chooseNewHash();
            identity.hash = fresh;
        }
    }

    StationLayout layout;
    StationIdentity identity;
    cs2::HashGuard hashGuard;
    StationState state;
    SystemCommands system;
    LocoCommands locos;
    MfxRegistry mfx;
    DecoderProgramming programming;
    AccessoryCommands accessories;
    FeedbackService feedback;
    DeviceService devices;
    ConfigDataService configData;
    MemoryFunctions memory;
};

SimulatedStation::SimulatedStation(StationLayout layout, QObject* parent)
    : SimulatedStation(std::move(layout), Options{}, parent) {}

SimulatedStation::SimulatedStation(StationLayout layout, Options options, QObject* parent)
    : QObject(parent),
      d_(std::make_unique<Private>(std::move(layout), options,
                                   [this](auto delay, auto work) { runLater(delay, std::move(work)); })) {}

SimulatedStation::~SimulatedStation() = default;

void SimulatedStation::receive(const can::CanFrame& frame) {
    emit frameReceived(frame);
    if (mcan::isMcan(frame))
        return; // an MS1's or its master's: the CS2 reads those as M-CAN, never as CS2 commands
    const auto decoded = cs2::decode(frame);
    if (!decoded)
        return; // a real station drops frames it cannot read
    d_->watchHash(frame);
    if (decoded->response && !std::holds_alternative<cs2::ConfigDataRequest>(decoded->body))
        return; // answers and events of other devices are not commands
    Outbox out(d_->identity.hash);
    d_->dispatch(*decoded, out);
    emitAll(out.take());
}

void SimulatedStation::setContact(std::uint16_t device, std::uint16_t contact, bool occupied) {
    Outbox out(d_->identity.hash);
    d_->feedback.change(device, contact, occupied, out);
    emitAll(out.take());
}

void SimulatedStation::setTrackLoad(int milliampere) {
    Outbox out(d_->identity.hash);
    d_->devices.setTrackLoad(milliampere);
    d_->devices.watchLoad(out);
    emitAll(out.take());
}

void SimulatedStation::announcePower() {
    Outbox out(d_->identity.hash);
    switch (d_->state.power) {
    case Power::Stopped:
        out.respond(cs2::SystemStop{0});
        break;
    case Power::Running:
        out.respond(cs2::SystemGo{0});
        break;
    case Power::Halted:
        out.respond(cs2::SystemHalt{0});
        break;
    }
    emitAll(out.take());
}

// Work the station does on its own later (a route's steps after their waits), its frames sent then.
void SimulatedStation::runLater(std::chrono::milliseconds delay, std::function<void(Outbox&)> work) {
    QTimer::singleShot(delay, this, [this, work = std::move(work)] {
        Outbox out(d_->identity.hash);
        work(out);
        emitAll(out.take());
    });
}

void SimulatedStation::emitAll(std::vector<can::CanFrame> frames) {
    if (!frames.empty())
        emit framesEmitted(frames);
}

std::uint32_t SimulatedStation::uid() const {
    return d_->identity.uid;
}
std::uint16_t SimulatedStation::hash() const {
    return d_->identity.hash;
}
SimulatedStation::Power SimulatedStation::power() const {
    return d_->state.power;
}
const StationLayout& SimulatedStation::layout() const {
    return d_->layout;
}
const StatusChannels& SimulatedStation::statusChannels() const {
    return d_->devices.stationChannels();
}

const SimulatedLoco* SimulatedStation::loco(std::uint32_t locId) const {
    return d_->state.findLoco(locId);
}

std::optional<std::uint8_t> SimulatedStation::accessoryPosition(std::uint32_t locId) const {
    const auto it = d_->state.accessories.find(locId);
    if (it == d_->state.accessories.end())
        return std::nullopt;
    return it->second;
}

bool SimulatedStation::contact(std::uint16_t device, std::uint16_t contact) const {
    const auto it = d_->state.contacts.find(std::uint32_t(device) << 16 | contact);
    return it != d_->state.contacts.end() && it->second.occupied;
}

} // namespace stellwerk::sim
