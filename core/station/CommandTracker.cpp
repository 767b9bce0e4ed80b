#include "station/CommandTracker.h"

#include "cs2/Codec.h"

#include <QTimer>
#include <algorithm>

namespace stellwerk::station {

const char* commandStatusName(CommandResult::Status status) {
    switch (status) {
    case CommandResult::Status::Acknowledged:
        return "acknowledged";
    case CommandResult::Status::Rejected:
        return "rejected";
    case CommandResult::Status::TimedOut:
        return "no acknowledgement";
    case CommandResult::Status::NotSent:
        return "not sent";
    case CommandResult::Status::Cancelled:
        return "cancelled";
    }
    return "?";
}

CommandTracker::CommandTracker(FrameSink sink, FrameWithdrawal withdraw, QObject* parent)
    : QObject(parent), sink_(std::move(sink)), withdraw_(std::move(withdraw)), timer_(new QTimer(this)) {
    timer_->setSingleShot(true);
    timer_->setTimerType(Qt::PreciseTimer);
    connect(timer_, &QTimer::timeout, this, &CommandTracker::expire);
}

CommandTracker::~CommandTracker() = default;

CommandId CommandTracker::send(const cs2::Message& command, CommandCallback done, CommandPolicy policy) {
    const auto key = ackKeyOf(command);
    if (!key) {
        if (done)
            done({CommandResult::Status::NotSent, std::nullopt, 0});
        return 0;
    }
    return sendFrames({cs2::encode(command)}, *key, std::move(done), policy);
}

CommandId CommandTracker::sendFrames(std::vector<can::CanFrame> frames, AckKey key, CommandCallback done,
                                     CommandPolicy policy) {
    const CommandId id = nextId_++;
    Pending& pending = pending_[id];
    pending.frames = std::move(frames);
    pending.key = key;
    pending.done = std::move(done);
    pending.policy = policy;
    pending.deadline = deadlines_.end();
    byKey_[key].push_back(id);
    if (!transmit(id, pending)) {
        finish(id, CommandResult::Status::NotSent);
        return 0;
    }
    return id;
}

bool CommandTracker::transmit(CommandId id, Pending& pending) {
    if (pending.deadline != deadlines_.end())
        deadlines_.erase(pending.deadline);
    if (pending.attempts > 0)
        withdraw(id); // a retry replaces what of the last attempt still waits
    ++pending.attempts;
    const auto now = Clock::now();
    if (pending.attempts == 1)
        pending.firstSent = now;
    pending.deadline = deadlines_.emplace(now + pending.policy.timeout, id);
    scheduleTimer();
    return sink_(pending.frames, id);
}

void CommandTracker::withdraw(CommandId id) {
    if (withdraw_)
        withdraw_(id);
}

bool CommandTracker::offer(const cs2::Message& answer) {
    if (!answer.response)
        return false;
    const auto key = ackKeyOf(answer);
    if (!key)
        return false;
    const auto waiting = byKey_.find(*key);
    if (waiting == byKey_.end())
        return false;
    const CommandId id = waiting->second.front();
    finish(id, isRejection(answer) ? CommandResult::Status::Rejected : CommandResult::Status::Acknowledged,
           answer);
    return true;
}

void CommandTracker::forget(CommandId id) {
    const auto it = pending_.find(id);
    if (it == pending_.end())
        return;
    unlink(id, it->second);
    pending_.erase(it);
    withdraw(id);
    scheduleTimer();
}

void CommandTracker::cancelAll() {
    std::vector<CommandId> ids;
    for (const auto& [id, pending] : pending_)
        ids.push_back(id);
    std::sort(ids.begin(), ids.end());
    for (CommandId id : ids)
        if (pending_.count(id))
            finish(id, CommandResult::Status::Cancelled);
}

void CommandTracker::expire() {
    const auto now = Clock::now();
    while (!deadlines_.empty() && deadlines_.begin()->first <= now) {
        const CommandId id = deadlines_.begin()->second;
        Pending& pending = pending_.at(id);
        if (pending.attempts > pending.policy.retries) {
            const auto firstSent = pending.firstSent;
            const bool telling = pending.policy.silenceMeansTrouble;
            finish(id, CommandResult::Status::TimedOut);
            if (giveUpObserver_ && telling)
                giveUpObserver_(firstSent);
            continue;
        }
        ++retriesSent_;
        if (!transmit(id, pending))
            finish(id, CommandResult::Status::NotSent);
    }
    scheduleTimer();
}

void CommandTracker::scheduleTimer() {
    if (deadlines_.empty()) {
        timer_->stop();
        return;
    }
    const auto wait = std::chrono::ceil<std::chrono::milliseconds>(deadlines_.begin()->first - Clock::now());
    timer_->start(std::max(wait, std::chrono::milliseconds(0)));
}

void CommandTracker::finish(CommandId id, CommandResult::Status status, std::optional<cs2::Message> answer) {
    auto it = pending_.find(id);
    CommandResult result{status, std::move(answer), it->second.attempts};
    CommandCallback done = std::move(it->second.done);
    unlink(id, it->second);
    pending_.erase(it);
    withdraw(id);
    if (done)
        done(result); // last: the callback may send the next command
}

void CommandTracker::unlink(CommandId id, Pending& pending) {
    if (pending.deadline != deadlines_.end())
        deadlines_.erase(pending.deadline);
    auto waiting = byKey_.find(pending.key);
    if (waiting == byKey_.end())
        return;
    auto& ids = waiting->second;
    ids.erase(std::remove(ids.begin(), ids.end(), id), ids.end());
    if (ids.empty())
        byKey_.erase(waiting);
}

} // namespace stellwerk::station
