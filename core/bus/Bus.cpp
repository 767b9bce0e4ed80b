#include "bus/Bus.h"

#include "transport/Transport.h"

#include <algorithm>

namespace stellwerk::bus {

Bus::Bus(transport::Transport& transport, busreading::BusProfile profile, QString name, QObject* parent)
    : QObject(parent), transport_(transport), profile_(std::move(profile)), name_(std::move(name)) {
    connect(&transport_, &transport::Transport::framesReceived, this, &Bus::receive);
    connect(&transport_, &transport::Transport::framesSent, this,
            [this](const std::vector<can::CanFrame>& frames) { emit framesSeen(frames, true); });
}

Bus::~Bus() {
    disconnect(&transport_, nullptr, this, nullptr);
    for (const Subscription& subscription : subscriptions_)
        disconnect(subscription.subscriber, nullptr, this, nullptr);
}

void Bus::subscribe(busreading::Protocol protocol, QObject* subscriber, Delivery deliver) {
    const bool known = subscribed(subscriber);
    subscriptions_.push_back({protocol, subscriber, std::move(deliver)});
    if (!known)
        connect(subscriber, &QObject::destroyed, this, [this, subscriber] { unsubscribe(subscriber); });
}

void Bus::unsubscribe(const QObject* subscriber) {
    std::erase_if(subscriptions_, [&](const Subscription& s) { return s.subscriber == subscriber; });
    disconnect(subscriber, nullptr, this, nullptr);
}

std::uint64_t Bus::received(busreading::Protocol protocol) const {
    return received_[std::size_t(protocol)];
}

void Bus::receive(const std::vector<can::CanFrame>& frames) {
    emit framesSeen(frames, false);
    std::array<std::vector<can::CanFrame>, busreading::ProtocolCount> sorted;
    for (const can::CanFrame& frame : frames)
        sorted[std::size_t(busreading::classify(frame, profile_))].push_back(frame);
    for (std::size_t protocol = 0; protocol < sorted.size(); ++protocol)
        received_[protocol] += sorted[protocol].size();
    // A delivery may subscribe or unsubscribe (a session that ends on what it read): work on a copy, and
    // skip whoever left meanwhile.
    const std::vector<Subscription> subscriptions = subscriptions_;
    for (const Subscription& subscription : subscriptions)
        if (const auto& batch = sorted[std::size_t(subscription.protocol)];
            !batch.empty() && subscribed(subscription.subscriber))
            subscription.deliver(batch);
}

bool Bus::subscribed(const QObject* subscriber) const {
    return std::any_of(subscriptions_.begin(), subscriptions_.end(),
                       [&](const Subscription& s) { return s.subscriber == subscriber; });
}

} // namespace stellwerk::bus
