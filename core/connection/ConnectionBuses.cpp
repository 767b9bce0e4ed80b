#include "connection/ConnectionBuses.h"

#include "connection/StationLink.h"

namespace stellwerk::connection {

ConnectionBuses::ConnectionBuses(QObject* parent) : QObject(parent) {}

ConnectionBuses::~ConnectionBuses() = default;

std::vector<BusInfo> ConnectionBuses::list() const {
    std::vector<BusInfo> buses;
    if (link_)
        for (const auto& bus : link_->buses)
            buses.push_back({bus->name(), bus->profile(), bus.get() == link_->buses.front().get()});
    return buses;
}

bool ConnectionBuses::isBusConnected(int index) const {
    return link_ && index >= 0 && std::size_t(index) < link_->transports.size() &&
           link_->transports[std::size_t(index)]->state() == transport::Transport::State::Connected;
}

std::uint64_t ConnectionBuses::busFrames(int index, busreading::Protocol protocol) const {
    if (!link_ || index < 0 || std::size_t(index) >= link_->buses.size())
        return 0;
    return link_->buses[std::size_t(index)]->received(protocol);
}

transport::TransportCounters ConnectionBuses::stationCounters() const {
    return link_ && !link_->transports.empty() ? link_->stationTransport().counters()
                                               : transport::TransportCounters{};
}

void ConnectionBuses::follow(const StationLink& link) {
    link_ = &link;
    connect(&link.stationBus(), &bus::Bus::framesSeen, this, &ConnectionBuses::stationFramesSeen);
    for (std::size_t index = 0; index < link.buses.size(); ++index)
        connect(link.buses[index].get(), &bus::Bus::framesSeen, this,
                [this, index](const std::vector<can::CanFrame>& frames, bool outgoing) {
                    emit busFramesSeen(int(index), frames, outgoing);
                });
    emit busesChanged();
}

void ConnectionBuses::release() {
    if (!link_)
        return;
    const bool hadBuses = !link_->buses.empty();
    link_->detach(this);
    link_ = nullptr;
    if (hadBuses)
        emit busesChanged();
}

} // namespace stellwerk::connection
