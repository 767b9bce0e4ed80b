#include "mcanhandhelds/HandheldMaster.h"

#include "mcanhandhelds/LocoFacts.h"

#include <algorithm>

namespace stellwerk::mcanhandhelds {
namespace {

// How long a frame we sent counts as the source of the same frame coming back (a gateway's echo).
constexpr std::chrono::seconds EchoWindow{2};
constexpr std::size_t EchoMemory = 256;

bool sameFrame(const can::CanFrame& a, const can::CanFrame& b) {
    return a == b;
}

} // namespace

HandheldMaster::HandheldMaster(Send send, MasterSettings settings, QObject* parent)
    : QObject(parent), send_(std::move(send)), settings_(settings),
      logins_(settings.uid, settings.loginStageTimeout), watcher_(settings.silentAfter) {
    ticker_.setInterval(settings_.tick);
    connect(&ticker_, &QTimer::timeout, this, &HandheldMaster::tick);
    ticker_.start();
}

HandheldMaster::~HandheldMaster() = default;

void HandheldMaster::setRailway(HandheldRailway* railway) {
    railway_ = railway;
    locomotivesChanged();
    powerChanged();
}

void HandheldMaster::setBook(HandheldBook* book) {
    book_ = book;
}

void HandheldMaster::receive(const std::vector<can::CanFrame>& frames) {
    const Clock::time_point now = Clock::now();
    for (const can::CanFrame& frame : frames)
        if (mcan::isMcan(frame))
            receiveOne(frame, now);
}

mcan::HandleRole HandheldMaster::roleOf(const can::CanFrame& frame) const {
    if (mcan::layoutOf(frame.id) != mcan::Layout::Session)
        return mcan::HandleRole::Unknown;
    const mcan::SessionId id = mcan::readSession(frame.id);
    if (id.handle == SlaveSession::SyHandle)
        return mcan::HandleRole::SystemStatus;
    const auto found = sessions_.find(std::uint8_t(id.node | 1));
    if (found == sessions_.end())
        return mcan::HandleRole::Unknown;
    const std::vector<std::uint32_t>& stack = found->second.session->handheld().stack;
    return id.handle >= SlaveSession::FirstLocoHandle && !stack.empty() ? mcan::HandleRole::Loco
                                                                        : mcan::HandleRole::Unknown;
}

void HandheldMaster::receiveOne(const can::CanFrame& frame, Clock::time_point now) {
    ++counters_.framesIn;
    if (isEcho(frame))
        return;
    const mcan::Message message = mcan::decode(frame, roleOf(frame));
    if (watcher_.observe(frame, now))
        emit handheldsChanged();
    if (spokeAsMaster(message, frame)) {
        otherMasterSpoke(frame);
        return;
    }
    if (!isMaster())
        return;
    switch (mcan::layoutOf(frame.id)) {
    case mcan::Layout::Login:
        receiveLogin(message, frame, now);
        break;
    case mcan::Layout::Flash:
        receiveFlash(message);
        break;
    case mcan::Layout::Session:
        receiveSession(message, frame, now);
        break;
    }
}

// A frame only a master sends, that we did not send: a login reply or grant, a session frame from an even
// node, the bus-busy frame of an MS1 master, a flash query.
bool HandheldMaster::spokeAsMaster(const mcan::Message& message, const can::CanFrame& frame) const {
    if (std::holds_alternative<mcan::LoginReply>(message) ||
        std::holds_alternative<mcan::LoginGrant>(message) || std::holds_alternative<mcan::BusBusy>(message) ||
        std::holds_alternative<mcan::FlashQuery>(message) ||
        std::holds_alternative<mcan::FlashStart>(message) || std::holds_alternative<mcan::FlashData>(message))
        return true;
    return mcan::layoutOf(frame.id) == mcan::Layout::Session && mcan::fromMaster(frame) &&
           !std::holds_alternative<mcan::Unknown>(message);
}

// Stellwerk stops being the master: its handhelds' locomotives are free, and it goes on showing the
// handhelds as a watcher.
void HandheldMaster::endSessions() {
    const Clock::time_point now = Clock::now();
    for (auto& [node, live] : sessions_) {
        live.session->releaseAll();
        watcher_.adopt(live.session->handheld(), now);
    }
    sessions_.clear();
    holders_.clear();
    afterAnswer_.clear();
}

void HandheldMaster::otherMasterSpoke(const can::CanFrame& frame) {
    if (otherMaster_)
        return;
    otherMaster_ = true;
    // A session frame names the master's node; a login or flash frame is on node 126 or 127 (not known).
    otherMasterNode_ = mcan::layoutOf(frame.id) == mcan::Layout::Session ? std::uint8_t(frame.id & 0x7F) : 0;
    endSessions();
    tell({HandheldEvent::Kind::Watching, 0, {}, 0, int(Watching::AnotherMaster), otherMasterNode_});
    emit handheldsChanged();
    emit masterChanged(false); // also when it was only waiting: the reason to watch changed
}

bool HandheldMaster::isEcho(const can::CanFrame& frame) {
    const Clock::time_point now = Clock::now();
    while (!sent_.empty() && now - sent_.front().second > EchoWindow)
        sent_.pop_front();
    const auto echo =
        std::find_if(sent_.begin(), sent_.end(), [&](const auto& s) { return sameFrame(s.first, frame); });
    if (echo == sent_.end())
        return false;
    sent_.erase(echo);
    return true;
}

// Sends the messages, then whatever was waiting to be told after an answer.
void HandheldMaster::send(const std::vector<mcan::Message>& messages) {
    std::vector<mcan::Message> all = messages;
    all.insert(all.end(), afterAnswer_.begin(), afterAnswer_.end());
    afterAnswer_.clear();
    if (all.empty() || !isMaster())
        return;
    std::vector<can::CanFrame> frames;
    const Clock::time_point now = Clock::now();
    for (const mcan::Message& message : all) {
        frames.push_back(mcan::encode(message));
        sent_.emplace_back(frames.back(), now);
        if (sent_.size() > EchoMemory)
            sent_.pop_front();
    }
    counters_.answers += frames.size();
    send_(frames);
}

// What one handheld's request makes the master tell the others goes out after the answer to the request.
void HandheldMaster::sendAfterAnswer(const std::vector<mcan::Message>& messages) {
    afterAnswer_.insert(afterAnswer_.end(), messages.begin(), messages.end());
}

void HandheldMaster::receiveLogin(const mcan::Message& message, const can::CanFrame&, Clock::time_point now) {
    LoginDesk::Outcome outcome;
    if (const auto* request = std::get_if<mcan::LoginRequest>(&message))
        outcome = logins_.receive(*request, now);
    else if (const auto* details = std::get_if<mcan::LoginDetails>(&message))
        outcome = logins_.receive(*details, now);
    else
        outcome.unexpected = true;
    counters_.unexpected += outcome.unexpected ? 1 : 0;
    send(outcome.replies);
    if (outcome.completed)
        completeLogin(*outcome.completed);
}

void HandheldMaster::completeLogin(const CompletedLogin& login) {
    const std::uint8_t node = freeSlaveNode(login.uid);
    if (node == 0) {
        ++counters_.unexpected; // every node pair is taken
        return;
    }
    if (SlaveSession* old = sessionOf(login.uid)) { // plugged in again: its old session ends
        old->releaseAll();
        sessions_.erase(old->slaveNode());
    }
    offline_.erase(login.uid);
    Handheld handheld;
    handheld.uid = login.uid;
    handheld.slaveNode = node;
    handheld.state = HandheldState::Upgrading;
    handheld.loginStage = 7;
    std::copy_n(login.details[3].begin() + 4, 4, handheld.version.begin());
    const std::optional<SavedHandheld> saved = book_ ? book_->load(login.uid) : std::nullopt;
    handheld.stack = saved ? saved->stack : firstLocos(std::size_t(handheld.stackSize));
    if (saved)
        handheld.name = saved->name;
    SessionHost& host = *this;
    auto session = std::make_unique<SlaveSession>(std::move(handheld), settings_.uid, host);
    const mcan::Message announce = session->announce();
    const mcan::LoginGrant grant{login.mid, login.uid, SlaveSession::StartHandle,
                                 node,      true,      0x00}; // never flash
    Live& live = sessions_[node];
    live.session = std::move(session);
    live.lastHeard = Clock::now();
    send({announce, grant});
    tell({HandheldEvent::Kind::LoggedIn, login.uid, live.session->handheld().name});
    emit handheldsChanged();
}

std::uint8_t HandheldMaster::freeSlaveNode(std::uint32_t uid) const {
    for (const auto& [node, live] : sessions_)
        if (live.session->handheld().uid == uid)
            return node; // the same handheld again: its own pair
    for (int node = settings_.nodeBase + 1; node < mcan::LoginNode; node += 2)
        if (!sessions_.contains(std::uint8_t(node)))
            return std::uint8_t(node);
    return 0;
}

void HandheldMaster::receiveSession(const mcan::Message& message, const can::CanFrame& frame,
                                    Clock::time_point now) {
    const auto found = sessions_.find(std::uint8_t(frame.id & 0x7F));
    if (found == sessions_.end() || !mcan::isSlaveNode(std::uint8_t(frame.id & 0x7F))) {
        ++counters_.unexpected; // a node nobody gave out here: it logs in again once it misses its master
        return;
    }
    Live& live = found->second;
    live.lastHeard = now;
    if (live.session->handheld().state == HandheldState::Silent) {
        live.session->handheld().state = HandheldState::Online;
        tell({HandheldEvent::Kind::Back, live.session->handheld().uid, live.session->handheld().name});
        emit handheldsChanged();
    }
    const HandheldState before = live.session->handheld().state;
    bool understood = true;
    send(live.session->answer(message, understood));
    counters_.unexpected += understood ? 0 : 1;
    if (before == HandheldState::Upgrading && live.session->handheld().state == HandheldState::Online)
        tell({HandheldEvent::Kind::UpgradeDone, live.session->handheld().uid, live.session->handheld().name});
}

void HandheldMaster::receiveFlash(const mcan::Message& message) {
    const auto* ready = std::get_if<mcan::FlashReady>(&message);
    if (!ready)
        return;
    Handheld& handheld = offline_[ready->uid];
    handheld.uid = ready->uid;
    if (handheld.state == HandheldState::FlashMode)
        return;
    handheld.state = HandheldState::FlashMode;
    tell({HandheldEvent::Kind::FlashMode, ready->uid, handheld.name});
    emit handheldsChanged();
}

void HandheldMaster::silenceBootLoader(std::uint32_t uid) {
    send({mcan::FlashStart{0, uid}});
}

void HandheldMaster::setActive(bool active) {
    if (active == active_)
        return;
    const bool wasMaster = isMaster();
    active_ = active;
    if (!active_) {
        endSessions();
        emit handheldsChanged();
    }
    if (wasMaster != isMaster())
        emit masterChanged(isMaster());
}

void HandheldMaster::standDown(Watching why) {
    const bool changed = why != why_ || active_;
    why_ = why;
    setActive(false);
    if (!changed)
        return;
    tell({HandheldEvent::Kind::Watching, 0, {}, 0, int(why)});
    emit masterChanged(isMaster());
}

Watching HandheldMaster::watching() const {
    if (!active_ && why_ == Watching::CentralStation)
        return Watching::CentralStation; // the master that spoke is the Central Station's
    if (otherMaster_)
        return Watching::AnotherMaster;
    if (!active_)
        return why_ == Watching::No ? Watching::Asked : why_;
    return Watching::No;
}

std::vector<Handheld> HandheldMaster::handhelds() const {
    std::vector<Handheld> list;
    for (const auto& [node, live] : sessions_)
        list.push_back(live.session->handheld());
    for (const Handheld& watched : watcher_.handhelds())
        if (!isMaster())
            list.push_back(watched);
    for (const auto& [uid, handheld] : offline_)
        list.push_back(handheld);
    return list;
}

SlaveSession* HandheldMaster::sessionOf(std::uint32_t uid) {
    for (auto& [node, live] : sessions_)
        if (live.session->handheld().uid == uid)
            return live.session.get();
    return nullptr;
}

void HandheldMaster::tell(HandheldEvent event) {
    emit this->event(event);
}

} // namespace stellwerk::mcanhandhelds
