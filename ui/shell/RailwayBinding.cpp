#include "shell/RailwayBinding.h"

#include "connection/StationConnection.h"
#include "model/Railway.h"
#include "model/RailwayHandhelds.h"

namespace stellwerk::ui {

RailwayBinding::RailwayBinding(connection::StationConnection& connection, QObject* parent)
    : QObject(parent), connection_(connection) {
    using connection::StationConnection;
    connect(&connection_, &StationConnection::sessionStarted, this, &RailwayBinding::sessionStarted);
    connect(&connection_, &StationConnection::configurationLoaded, this,
            &RailwayBinding::configurationLoaded);
    connect(&connection_, &StationConnection::stateChanged, this, &RailwayBinding::connectionStateChanged);
    if (station::StationSession* session = connection_.session()) {
        sessionStarted(session);
        if (connection_.state() == StationConnection::State::Ready)
            configurationLoaded(connection_.startupResult());
    }
}

RailwayBinding::~RailwayBinding() {
    delete railway_;
}

// The railway of the session, and the handhelds on the station's bus driving it.
void RailwayBinding::sessionStarted(station::StationSession* session) {
    auto* railway = new model::Railway(*session);
    if (mcanhandhelds::HandheldMaster* master = connection_.handhelds().master())
        new model::RailwayHandhelds(*railway, *master, railway);
    replace(railway);
}

void RailwayBinding::configurationLoaded(const station::StartupResult& result) {
    if (railway_)
        railway_->load(result);
}

// A disconnect releases the session at the next turn of the event loop: the railway goes now.
void RailwayBinding::connectionStateChanged() {
    if (railway_ && !connection_.session())
        replace(nullptr);
}

void RailwayBinding::replace(model::Railway* railway) {
    model::Railway* previous = railway_;
    railway_ = railway;
    emit railwayChanged(railway_);
    delete previous;
}

} // namespace stellwerk::ui
