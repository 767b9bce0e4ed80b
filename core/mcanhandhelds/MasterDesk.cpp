#include "mcanhandhelds/HandheldMaster.h"
#include "mcanhandhelds/LocoFacts.h"

// The master's side towards the railway and over time: what the sessions ask of it (SessionHost), the
// railway's changes told to the handhelds, people's changes to stacks and names, and the liveness ticks.

namespace stellwerk::mcanhandhelds {

const HandheldLoco* HandheldMaster::loco(std::uint32_t locId) const {
    for (const HandheldLoco& loco : locos_)
        if (loco.locId == locId)
            return &loco;
    return nullptr;
}

LocoDrive HandheldMaster::drive(std::uint32_t locId) const {
    const std::optional<LocoDrive> drive = railway_ ? railway_->drive(locId) : std::nullopt;
    return drive.value_or(LocoDrive{});
}

// Unknown power counts as stopped: a handheld must not show "go" that nobody confirmed.
bool HandheldMaster::stopped() const {
    return !railway_ || railway_->powerOn() != std::optional<bool>(true);
}

bool HandheldMaster::take(SlaveSession& session, std::uint32_t locId) {
    const std::uint32_t uid = session.handheld().uid;
    const auto holder = holders_.find(locId);
    if (holder != holders_.end() && holder->second != uid && settings_.exclusive) {
        tell({HandheldEvent::Kind::LocoRefused, uid, session.handheld().name, locId});
        return false;
    }
    if (const std::optional<std::uint32_t> previous = session.handheld().loco; previous && *previous != locId)
        release(session, *previous); // a handheld drives one locomotive at a time
    holders_[locId] = uid;
    const HandheldLoco* known = loco(locId);
    session.handheld().locoName = known ? QString::fromStdString(handheldName(known->name)) : QString();
    for (auto& [node, live] : sessions_)
        if (live.session.get() != &session && settings_.exclusive)
            sendAfterAnswer(live.session->holderChanged(locId, true));
    tell({HandheldEvent::Kind::LocoTaken, uid, session.handheld().name, locId});
    return true;
}

void HandheldMaster::release(SlaveSession& session, std::uint32_t locId) {
    const auto holder = holders_.find(locId);
    if (holder == holders_.end() || holder->second != session.handheld().uid)
        return;
    holders_.erase(holder);
    for (auto& [node, live] : sessions_)
        if (live.session.get() != &session && settings_.exclusive)
            sendAfterAnswer(live.session->holderChanged(locId, false));
    tell({HandheldEvent::Kind::LocoReleased, session.handheld().uid, session.handheld().name, locId});
}

bool HandheldMaster::heldByOther(const SlaveSession& session, std::uint32_t locId) const {
    const auto holder = holders_.find(locId);
    return settings_.exclusive && holder != holders_.end() && holder->second != session.handheld().uid;
}

void HandheldMaster::drive(SlaveSession& session, std::uint32_t locId, std::uint8_t function,
                           std::uint8_t value) {
    if (heldByOther(session, locId)) {
        ++counters_.refused; // only the handheld that holds it drives it
        return;
    }
    if (!holders_.contains(locId) && !take(session, locId))
        return;
    driveRailway(session, locId, function, value);
    emit handheldsChanged();
}

void HandheldMaster::driveRailway(SlaveSession& session, std::uint32_t locId, std::uint8_t function,
                                  std::uint8_t value) {
    Handheld& handheld = session.handheld();
    if (function == 1) {
        const bool forward = (value & 0x80) == 0;
        const int speed = value & 0x7F;
        if (railway_ && drive(locId).forward != forward)
            railway_->setDirection(locId, forward);
        if (railway_)
            railway_->setSpeed(locId, railwaySpeed(speed));
        handheld.speed = speed;
        handheld.forward = forward;
        tell({HandheldEvent::Kind::Speed, handheld.uid, handheld.name, locId, speed, 0, forward});
        return;
    }
    const int index = function - 2;
    if (railway_)
        railway_->setFunction(locId, index, value != 0);
    const std::uint32_t bit = 1u << index;
    handheld.functions = value ? handheld.functions | bit : handheld.functions & ~bit;
    tell({HandheldEvent::Kind::Function, handheld.uid, handheld.name, locId, 0, index, true, value != 0});
}

void HandheldMaster::stopKey(SlaveSession& session, bool stop) {
    tell({stop ? HandheldEvent::Kind::Stop : HandheldEvent::Kind::Go, session.handheld().uid,
          session.handheld().name});
    if (railway_)
        railway_->setPower(!stop);
    shortCircuit_ = shortCircuit_ && stop;
    for (auto& [node, live] : sessions_) // every handheld shows it at once (7.4)
        sendAfterAnswer(live.session->status(stop, shortCircuit_));
}

void HandheldMaster::changed(SlaveSession& session) {
    const Handheld& handheld = session.handheld();
    if (book_ && !handheld.name.isEmpty())
        book_->save(handheld.uid, {handheld.name, handheld.stack});
    emit handheldsChanged();
}

void HandheldMaster::locoChanged(std::uint32_t locId) {
    if (!railway_ || !loco(locId))
        return;
    const LocoDrive now = drive(locId);
    for (auto& [node, live] : sessions_)
        send(live.session->driveChanged(locId, now));
    emit handheldsChanged();
}

void HandheldMaster::powerChanged() {
    shortCircuit_ = shortCircuit_ && stopped(); // the power back on ends it
    for (auto& [node, live] : sessions_)
        send(live.session->status(stopped(), shortCircuit_));
}

void HandheldMaster::shortCircuitReported() {
    shortCircuit_ = true;
    for (auto& [node, live] : sessions_)
        send(live.session->status(stopped(), true));
}

void HandheldMaster::locomotivesChanged() {
    locos_ = railway_ ? railway_->locomotives() : std::vector<HandheldLoco>{};
}

std::vector<std::uint32_t> HandheldMaster::firstLocos(std::size_t count) const {
    std::vector<std::uint32_t> stack;
    for (std::size_t i = 0; i < locos_.size() && i < count; ++i)
        stack.push_back(locos_[i].locId);
    return stack;
}

void HandheldMaster::setStack(std::uint32_t uid, const std::vector<std::uint32_t>& stack) {
    std::vector<std::uint32_t> kept(stack.begin(), stack.begin() + std::min<std::size_t>(stack.size(), 10));
    if (SlaveSession* session = sessionOf(uid)) {
        kept.resize(std::min<std::size_t>(kept.size(), std::size_t(session->handheld().stackSize)));
        send(session->setStack(kept));
        changed(*session);
        return;
    }
    if (book_) {
        SavedHandheld saved = book_->load(uid).value_or(SavedHandheld{});
        saved.stack = kept;
        book_->save(uid, saved);
    }
    emit handheldsChanged();
}

void HandheldMaster::rename(std::uint32_t uid, const QString& name) {
    const std::string shown = handheldName(name.toStdString());
    if (SlaveSession* session = sessionOf(uid)) {
        send(session->rename(shown));
        session->handheld().name = QString::fromStdString(shown);
        changed(*session);
    } else if (book_) {
        SavedHandheld saved = book_->load(uid).value_or(SavedHandheld{});
        saved.name = QString::fromStdString(shown);
        book_->save(uid, saved);
    }
    tell({HandheldEvent::Kind::Renamed, uid, QString::fromStdString(shown)});
    emit handheldsChanged();
}

void HandheldMaster::tick() {
    const Clock::time_point now = Clock::now();
    logins_.expire(now);
    if (watcher_.tick(now))
        emit handheldsChanged();
    std::vector<std::uint8_t> lost;
    for (auto& [node, live] : sessions_) {
        checkLiveness(live, now);
        if (live.session->handheld().state == HandheldState::Offline)
            lost.push_back(node);
    }
    for (const std::uint8_t node : lost)
        drop(node);
    send({}); // what the dropped handhelds' locomotives mean to the others
}

// 7.2.2: silent for the silence time, the master polls every second, at most masterPolls times, then ends it.
void HandheldMaster::checkLiveness(Live& live, Clock::time_point now) {
    Handheld& handheld = live.session->handheld();
    if (handheld.state != HandheldState::Silent) {
        if (now - live.lastHeard <= settings_.silentAfter)
            return;
        handheld.state = HandheldState::Silent;
        handheld.silentPollsLeft = settings_.masterPolls;
        live.nextPoll = now;
        tell({HandheldEvent::Kind::Silent, handheld.uid, handheld.name});
        emit handheldsChanged();
    }
    if (now < live.nextPoll)
        return;
    if (handheld.silentPollsLeft == 0) {
        handheld.state = HandheldState::Offline;
        return;
    }
    --handheld.silentPollsLeft;
    live.nextPoll = now + settings_.masterPollEvery;
    send({live.session->masterPoll()});
    emit handheldsChanged();
}

void HandheldMaster::drop(std::uint8_t slaveNode) {
    const auto found = sessions_.find(slaveNode);
    if (found == sessions_.end())
        return;
    found->second.session->releaseAll();
    Handheld handheld = found->second.session->handheld();
    handheld.state = HandheldState::Offline;
    handheld.loco.reset();
    sessions_.erase(found);
    offline_[handheld.uid] = handheld;
    tell({HandheldEvent::Kind::Lost, handheld.uid, handheld.name});
    emit handheldsChanged();
}

} // namespace stellwerk::mcanhandhelds
