#include "model/RailwayFollower.h"

#include "model/Railway.h"
#include "model/ThrottlePort.h"

namespace stellwerk::model {

RailwayFollower::RailwayFollower(Changes changes) : changes_(std::move(changes)) {}

RailwayFollower::~RailwayFollower() {
    letGo();
}

void RailwayFollower::follow(Railway* railway) {
    letGo();
    if (!railway)
        return;
    const Changes& c = changes_;
    const auto add = [this](QMetaObject::Connection connection) { connections_.push_back(connection); };
    if (c.loaded)
        add(QObject::connect(railway, &Railway::loaded, c.loaded));
    if (c.locomotives) {
        add(QObject::connect(railway, &Railway::locomotivesChanged, c.locomotives));
        add(QObject::connect(railway, &Railway::locomotiveCommandAcknowledged,
                             [f = c.locomotives](quint32 loco) { f({loco}); }));
    }
    if (c.accessories)
        add(QObject::connect(railway, &Railway::accessoriesChanged, c.accessories));
    if (c.addresses)
        add(QObject::connect(railway, &Railway::addressesChanged, c.addresses));
    if (c.routeFinished)
        add(QObject::connect(railway, &Railway::routeFinished, [f = c.routeFinished] { f(); }));
    if (c.power) {
        add(QObject::connect(railway, &Railway::powerChanged, [f = c.power] { f(); }));
        add(QObject::connect(railway, &Railway::stateReportedChanged, [f = c.power] { f(); }));
    }
    if (c.takenOver)
        add(QObject::connect(&railway->throttlePort().owners(), &LocoOwners::takenOver, c.takenOver));
    if (c.gone)
        add(QObject::connect(railway, &QObject::destroyed, [f = c.gone] { f(); }));
}

void RailwayFollower::letGo() {
    for (const QMetaObject::Connection& connection : connections_)
        QObject::disconnect(connection);
    connections_.clear();
}

} // namespace stellwerk::model
