#include "binding/RailwayBinding.h"

#include "connection/StationConnection.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "model/RailwayDevices.h"
#include "model/RailwayHandhelds.h"
#include "model/RailwayThrottles.h"

namespace stellwerk::binding {

RailwayBinding::RailwayBinding(model::LayoutInUse* layout, QObject* parent)
    : QObject(parent), layout_(layout) {}

RailwayBinding::RailwayBinding(connection::StationConnection& connection, model::LayoutInUse* layout,
                               QObject* parent)
    : QObject(parent), connection_(&connection), layout_(layout) {
    follow();
}

// Nothing keeps the station's railway and download current any more: both go.
RailwayBinding::~RailwayBinding() {
    if (layout_)
        layout_->forgetStation();
    retire(railway_);
}

// The connection's session as it is now, and from now on what happens to it.
void RailwayBinding::follow() {
    using connection::StationConnection;
    connect(connection_, &StationConnection::sessionStarted, this, [this](station::StationSession* session) {
        sessionStarted(*session, connection_->handhelds().master());
    });
    connect(connection_, &StationConnection::configurationLoaded, this, &RailwayBinding::configurationLoaded);
    // A disconnect releases the session at the next turn of the event loop: the railway goes now.
    connect(connection_, &StationConnection::stateChanged, this, [this] {
        if (!connection_->session())
            sessionEnded();
    });
    connect(&connection_->devices(), &connection::ConnectionDevices::devicesChanged, this,
            &RailwayBinding::followDevices);
    if (layout_)
        connect(layout_, &model::LayoutInUse::changed, this, [this] {
            connection_->pictures().setFolder(QString::fromStdString(layout_->picturesFolder().string()));
        });
    followDevices();
    if (station::StationSession* session = connection_->session()) {
        sessionStarted(*session, connection_->handhelds().master());
        if (connection_->state() == StationConnection::State::Ready)
            configurationLoaded(connection_->startupResult());
    }
}

void RailwayBinding::followDevices() {
    devicesChanged(connection_->devices().orcSession(), connection_->devices().roModules());
}

void RailwayBinding::bindDevices(std::function<model::DeviceBindings()> bindingsOf) {
    bindingsOf_ = std::move(bindingsOf);
    if (railway_ && !devices_)
        bindDevicesOf(*railway_);
}

void RailwayBinding::sessionStarted(station::StationSession& session,
                                    mcanhandhelds::HandheldMaster* handhelds) {
    auto* railway = new model::Railway(session);
    if (handhelds)
        new model::RailwayHandhelds(*railway, *handhelds, railway);
    if (bindingsOf_)
        bindDevicesOf(*railway);
    if (layout_) // a new session may be another station: its download comes with its start-up
        layout_->forgetStation();
    replace(railway);
}

void RailwayBinding::configurationLoaded(const station::StartupResult& result) {
    if (railway_)
        railway_->load(result); // first: whoever follows the layout finds the railway loaded with it
    if (layout_)
        layout_->useStationDownload(result);
}

void RailwayBinding::sessionEnded() {
    if (railway_)
        replace(nullptr);
    if (layout_)
        layout_->forgetStation();
}

void RailwayBinding::devicesChanged(orccentral::OrcSession* orc,
                                    const std::vector<romodule::RoModuleSession*>& modules) {
    orc_ = orc;
    modules_ = modules;
    if (devices_)
        devices_->setSessions(orc_, modules_);
    if (throttles_)
        throttles_->setSession(orc_);
}

// The railway's accessories and contacts that devices switch and light, and the locos the OpenRailCAN
// throttles drive, on the device sessions open now.
void RailwayBinding::bindDevicesOf(model::Railway& railway) {
    devices_ = new model::RailwayDevices(railway, bindingsOf_(), &railway);
    throttles_ = new model::RailwayThrottles(railway, &railway);
    devices_->setSessions(orc_, modules_);
    throttles_->setSession(orc_);
}

void RailwayBinding::replace(model::Railway* railway) {
    model::Railway* previous = railway_;
    railway_ = railway;
    emit railwayChanged(railway_);
    retire(previous);
}

// What the binding hung on a railway lets go of it first: their destructors still talk to the railway,
// which must not be half destroyed by then (as it is while ~QObject deletes its children).
void RailwayBinding::retire(model::Railway* railway) {
    if (!railway)
        return;
    qDeleteAll(railway->findChildren<model::RailwayDevices*>(Qt::FindDirectChildrenOnly));
    qDeleteAll(railway->findChildren<model::RailwayThrottles*>(Qt::FindDirectChildrenOnly));
    qDeleteAll(railway->findChildren<model::RailwayHandhelds*>(Qt::FindDirectChildrenOnly));
    delete railway;
}

} // namespace stellwerk::binding
