#include "sim/SimulatedBus.h"

#include <algorithm>
#include <deque>
#include <utility>

namespace stellwerk::sim {

SimulatedBus::SimulatedBus(QObject* parent) : QObject(parent) {
    roundClock_.setSingleShot(true);
    roundClock_.setInterval(0);
    connect(&roundClock_, &QTimer::timeout, this, &SimulatedBus::deliverRound);
}

SimulatedBus::~SimulatedBus() {
    for (const Peer& peer : peers_)
        peer.object->disconnect(this);
}

void SimulatedBus::add(QObject& peer, std::function<void(const can::CanFrame&)> receive) {
    peers_.push_back({&peer, std::move(receive)});
    connect(&peer, &QObject::destroyed, this, [this](QObject* gone) { detach(*gone); });
}

void SimulatedBus::detach(QObject& peer) {
    std::erase_if(peers_, [&peer](const Peer& known) { return known.object == &peer; });
    peer.disconnect(this);
}

void SimulatedBus::putFromOutside(const std::vector<can::CanFrame>& frames) {
    put(frames, nullptr);
}

void SimulatedBus::put(const std::vector<can::CanFrame>& frames, const QObject* sender) {
    for (const can::CanFrame& frame : frames)
        if (!mergeIntoRound(frame, sender))
            round_.push_back({frame, {sender}});
    if (!round_.empty() && !roundClock_.isActive())
        roundClock_.start();
}

// Two peers sending the same frame in one round: the bus carries it once. A peer's own repetitions, and
// frames from the outside, stay separate frames.
bool SimulatedBus::mergeIntoRound(const can::CanFrame& frame, const QObject* sender) {
    if (!sender)
        return false;
    for (Pending& pending : round_) {
        const bool byPeers = pending.senders.front() != nullptr;
        if (byPeers && pending.frame == frame &&
            std::ranges::find(pending.senders, sender) == pending.senders.end()) {
            pending.senders.push_back(sender);
            return true;
        }
    }
    return false;
}

void SimulatedBus::deliverRound() {
    const std::vector<Pending> round = arbitrate(std::exchange(round_, {}));
    std::vector<can::CanFrame> carried;
    for (const Pending& pending : round)
        if (pending.senders.front() != nullptr)
            carried.push_back(pending.frame);
    if (!carried.empty())
        emit framesCarried(carried);
    const std::vector<Peer> peers = peers_; // a peer may leave the bus while it receives
    for (const Pending& pending : round)
        for (const Peer& peer : peers)
            if (std::ranges::find(pending.senders, peer.object) == pending.senders.end() &&
                attached(peer.object))
                peer.receive(pending.frame);
}

// Each sender queues its frames; the queue whose next frame has the lowest identifier sends next.
std::vector<SimulatedBus::Pending> SimulatedBus::arbitrate(std::vector<Pending> round) {
    std::vector<std::pair<const QObject*, std::deque<std::size_t>>> queues;
    for (std::size_t i = 0; i < round.size(); ++i) {
        const QObject* sender = round[i].senders.front();
        auto queue = std::ranges::find(queues, sender, &decltype(queues)::value_type::first);
        if (queue == queues.end())
            queue = queues.insert(queues.end(), {sender, {}});
        queue->second.push_back(i);
    }
    std::vector<Pending> ordered;
    ordered.reserve(round.size());
    while (!queues.empty()) {
        const auto next = std::ranges::min_element(
            queues, {}, [&round](const auto& queue) { return round[queue.second.front()].frame.id; });
        ordered.push_back(std::move(round[next->second.front()]));
        next->second.pop_front();
        if (next->second.empty())
            queues.erase(next);
    }
    return ordered;
}

bool SimulatedBus::attached(const QObject* object) const {
    return std::ranges::find(peers_, object, &Peer::object) != peers_.end();
}

} // namespace stellwerk::sim
