#include "connection/ConnectionHandhelds.h"

#include "connection/StationLink.h"

namespace stellwerk::connection {

ConnectionHandhelds::ConnectionHandhelds(HandheldSettings settings, QObject* parent)
    : QObject(parent), settings_(std::move(settings)) {}

ConnectionHandhelds::~ConnectionHandhelds() = default;

mcanhandhelds::HandheldMaster* ConnectionHandhelds::master() const {
    return link_ && link_->handhelds ? &link_->handhelds->master() : nullptr;
}

void ConnectionHandhelds::setRole(HandheldRole role) {
    settings_.role = role;
    if (link_ && link_->handhelds)
        link_->handhelds->setRole(role, {}); // it knows the devices the last start-up listed
}

void ConnectionHandhelds::open(StationLink& link) {
    link.handhelds = std::make_unique<HandheldConnection>(link.stationBus(), settings_);
    link_ = &link;
    emit masterReplaced();
}

void ConnectionHandhelds::release() {
    if (!link_)
        return;
    link_ = nullptr;
    emit masterReplaced();
}

} // namespace stellwerk::connection
