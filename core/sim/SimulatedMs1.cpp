#include "sim/SimulatedMs1.h"

#include "mcan/Codec.h"
#include "sim/Ms1Driver.h"
#include "sim/Ms1Keys.h"
#include "sim/Ms1Login.h"
#include "sim/Ms1MasterFrames.h"
#include "sim/Ms1Upgrade.h"

#include <QTimer>
#include <utility>

namespace stellwerk::sim {

using Event = Ms1Outbox::Event;

// The MS1's conversation: the login, the session (upgrade, polls, the master's frames) and its two clocks,
// one for the login's retries and one ticking every poll period while logged in.
class SimulatedMs1::Private {
public:
    Private(Options options, SimulatedMs1& owner)
        : identity(std::move(options.identity)), timing(options.timing), login(identity.uid), upgrade(memory),
          keys(memory), masterFrames(identity, memory, upgrade, keys), loginClock(&owner), tick(&owner) {
        loginClock.setSingleShot(true);
    }

    void startLogin(Ms1Outbox& out);
    void stop();
    void receiveLogin(const can::CanFrame& frame, Ms1Outbox& out);
    void receiveSession(const can::CanFrame& frame, Ms1Outbox& out);
    void onTick(Ms1Outbox& out);
    bool online() const { return phase == Phase::Online; }

    Ms1Identity identity;
    Timing timing;
    Phase phase = Phase::Unplugged;
    Ms1Memory memory;
    Ms1Login login;
    Ms1Upgrade upgrade;
    Ms1Keys keys;
    Ms1MasterFrames masterFrames;
    QTimer loginClock;
    QTimer tick;
    int silentTicks = 0;   // polls (or, in the upgrade, ticks) since the master last said anything
    int pollsAnswered = 0; // since the upgrade ended
    bool tookFirstEntry = false;

private:
    void startSession(Ms1Outbox& out);
    void finishUpgrade(Ms1Outbox& out);
    void sendPoll(Ms1Outbox& out);
    void pollAnswered(Ms1Outbox& out);
    mcan::HandleRole roleOf(std::uint16_t handle) const;
};

void SimulatedMs1::Private::startLogin(Ms1Outbox& out) {
    phase = Phase::LoggingIn;
    tick.stop();
    upgrade.reset();
    memory = Ms1Memory{};
    out.frames.push_back(login.start());
    loginClock.start(timing.loginRetry);
}

void SimulatedMs1::Private::stop() {
    login.stop();
    upgrade.reset();
    loginClock.stop();
    tick.stop();
}

// A lost stage waits for the login clock, which then starts again at stage 0 (loginTimeout).
void SimulatedMs1::Private::receiveLogin(const can::CanFrame& frame, Ms1Outbox& out) {
    if (phase != Phase::LoggingIn)
        return;
    const mcan::Message message = mcan::decode(frame);
    if (const auto* reply = std::get_if<mcan::LoginReply>(&message)) {
        if (login.onReply(*reply, out.frames) != Ms1Login::Outcome::Ignored)
            loginClock.start(timing.loginRetry);
        return;
    }
    const auto* grant = std::get_if<mcan::LoginGrant>(&message);
    const Ms1Login::Outcome outcome = grant ? login.onGrant(*grant) : Ms1Login::Outcome::Ignored;
    if (outcome == Ms1Login::Outcome::Granted) {
        startSession(out);
    } else if (outcome == Ms1Login::Outcome::FlashMode) {
        stop();
        phase = Phase::FlashMode;
        out.send(mcan::FlashReady{identity.uid});
        out.tell(Event::FlashMode);
    }
}

void SimulatedMs1::Private::startSession(Ms1Outbox& out) {
    loginClock.stop();
    phase = Phase::Upgrading;
    memory = Ms1Memory{};
    memory.link.node = login.grant().node;
    memory.link.startHandle = login.grant().startHandle;
    memory.capacity = identity.stackSize;
    silentTicks = 0;
    pollsAnswered = 0;
    tookFirstEntry = false;
    tick.start(timing.pollPeriod);
    out.tell(Event::LoggedIn, memory.link.node);
    upgrade.start(login.masterWantsDescription(), out);
}

// The MS1 listens to its master's node only (document 5.4.1).
void SimulatedMs1::Private::receiveSession(const can::CanFrame& frame, Ms1Outbox& out) {
    if (phase != Phase::Upgrading && phase != Phase::Online)
        return;
    const mcan::SessionId id = mcan::readSession(frame.id);
    if (id.node != memory.link.masterNode())
        return;
    silentTicks = 0;
    const mcan::Message message = mcan::decode(frame, roleOf(id.handle));
    if (upgrade.take(frame, message, out)) {
        if (phase == Phase::Upgrading && upgrade.done())
            finishUpgrade(out);
        return;
    }
    if (std::holds_alternative<mcan::PollAnswer>(message))
        pollAnswered(out);
    else
        masterFrames.take(message, out);
}

mcan::HandleRole SimulatedMs1::Private::roleOf(std::uint16_t handle) const {
    const Ms1Link& link = memory.link;
    if (link.syHandle != 0 && handle == link.syHandle)
        return mcan::HandleRole::SystemStatus;
    if (memory.indexOf(handle))
        return mcan::HandleRole::Loco;
    if (link.sdHandle != 0 && handle == link.sdHandle)
        return mcan::HandleRole::SlaveDescription;
    if (handle == link.startHandle)
        return mcan::HandleRole::Start;
    return handle == Ms1Link::PollHandle ? mcan::HandleRole::Poll : mcan::HandleRole::Unknown;
}

// There is no end-of-upgrade frame: the first poll says it (notes B§3.2 step 7, trace #82).
void SimulatedMs1::Private::finishUpgrade(Ms1Outbox& out) {
    phase = Phase::Online;
    sendPoll(out);
    out.tell(Event::UpgradeDone);
}

void SimulatedMs1::Private::sendPoll(Ms1Outbox& out) {
    const Ms1Link& link = memory.link;
    out.send(mcan::Poll{link.at(Ms1Link::PollHandle, mcan::prio::Master), link.masterNode()});
    ++silentTicks;
}

// After a restart the MS1 takes the first entry of its stack (6.7.5); the trace's did so after its fifth
// poll had been answered (#92).
void SimulatedMs1::Private::pollAnswered(Ms1Outbox& out) {
    ++pollsAnswered;
    if (tookFirstEntry || pollsAnswered < timing.pollsBeforeTake || !online())
        return;
    tookFirstEntry = true;
    if (!memory.shown)
        keys.take(0, out);
}

// Polls go out while online and not asking about an added locomotive (7.7.2); a master silent for
// pollsWithoutAnswer ticks is gone ("KEIN MASTER", 8): the MS1 logs in again.
void SimulatedMs1::Private::onTick(Ms1Outbox& out) {
    if (silentTicks >= timing.pollsWithoutAnswer) {
        out.tell(Event::MasterLost);
        startLogin(out);
        return;
    }
    if (online() && upgrade.done())
        sendPoll(out);
    else
        ++silentTicks;
}

SimulatedMs1::SimulatedMs1(QObject* parent) : SimulatedMs1(Options{}, parent) {}

SimulatedMs1::SimulatedMs1(Options options, QObject* parent)
    : QObject(parent), d_(std::make_unique<Private>(options, *this)) {
    connect(&d_->loginClock, &QTimer::timeout, this, [this] {
        Ms1Outbox out;
        d_->startLogin(out);
        flush(out);
    });
    connect(&d_->tick, &QTimer::timeout, this, [this] {
        Ms1Outbox out;
        d_->onTick(out);
        flush(out);
    });
    if (options.drivesNowAndThen)
        new Ms1Driver(*this, options.timing.driveEvery, this);
}

SimulatedMs1::~SimulatedMs1() = default;

void SimulatedMs1::receive(const can::CanFrame& frame) {
    if (!mcan::isMcan(frame))
        return;
    Ms1Outbox out;
    switch (mcan::layoutOf(frame.id)) {
    case mcan::Layout::Login:
        d_->receiveLogin(frame, out);
        break;
    case mcan::Layout::Session:
        d_->receiveSession(frame, out);
        break;
    case mcan::Layout::Flash: // flashing is the boot loader's business, never the MS1's
        break;
    }
    flush(out);
}

void SimulatedMs1::plugIn() {
    Ms1Outbox out;
    d_->stop();
    d_->startLogin(out);
    flush(out);
}

void SimulatedMs1::unplug() {
    d_->stop();
    d_->phase = Phase::Unplugged;
}

bool SimulatedMs1::takeLoco(int stackIndex) {
    Ms1Outbox out;
    const bool done = d_->online() && stackIndex >= 0 && d_->keys.take(std::size_t(stackIndex), out);
    flush(out);
    return done;
}

bool SimulatedMs1::setSpeed(int speed, Direction direction) {
    Ms1Outbox out;
    const bool done = d_->online() && d_->keys.drive(speed, direction == Direction::Reverse, out);
    flush(out);
    return done;
}

bool SimulatedMs1::setFunction(int function, bool on) {
    Ms1Outbox out;
    const bool done = d_->online() && d_->keys.function(function, on, out);
    flush(out);
    return done;
}

bool SimulatedMs1::pressStop() {
    Ms1Outbox out;
    const bool done = d_->online() && d_->keys.stopKey(true, out);
    flush(out);
    return done;
}

bool SimulatedMs1::pressGo() {
    Ms1Outbox out;
    const bool done = d_->online() && d_->keys.stopKey(false, out);
    flush(out);
    return done;
}

SimulatedMs1::Phase SimulatedMs1::phase() const {
    return d_->phase;
}

const Ms1Identity& SimulatedMs1::identity() const {
    return d_->identity;
}

const Ms1Memory& SimulatedMs1::memory() const {
    return d_->memory;
}

// Frames first, then what changed, so that a watcher that presses a key sees its frame after these.
void SimulatedMs1::flush(Ms1Outbox& out) {
    if (!out.frames.empty())
        emit framesEmitted(std::exchange(out.frames, {}));
    for (const auto& [event, value] : std::exchange(out.events, {}))
        announce(event, value);
}

void SimulatedMs1::announce(Ms1Outbox::Event event, int value) {
    switch (event) {
    case Event::LoggedIn:
        emit loggedIn(value);
        break;
    case Event::UpgradeDone:
        emit upgradeDone();
        break;
    case Event::LocoTaken:
        emit locoTaken(value);
        break;
    case Event::LocoRefused:
        emit locoRefused(value);
        break;
    case Event::MasterLost:
        emit masterLost();
        break;
    case Event::FlashMode:
        emit flashModeEntered();
        break;
    case Event::DisplayChanged:
        emit displayChanged();
        break;
    }
}

} // namespace stellwerk::sim
