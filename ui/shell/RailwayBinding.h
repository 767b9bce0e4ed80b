#pragma once

#include <QObject>

namespace stellwerk::connection {
class StationConnection;
}
namespace stellwerk::model {
class Railway;
}
namespace stellwerk::station {
class StationSession;
struct StartupResult;
} // namespace stellwerk::station

namespace stellwerk::ui {

// Gives the views a railway model for whatever station the connection is talking to: a new Railway
// for every session (created before its start-up runs, so that it keeps the start-up's state answers),
// loaded whenever a start-up finishes, and gone before its session goes. Views follow railwayChanged.
// It must be destroyed before the connection.
class RailwayBinding final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(RailwayBinding)

public:
    explicit RailwayBinding(connection::StationConnection& connection, QObject* parent = nullptr);
    ~RailwayBinding() override;

    // The railway of the current session, or null while there is none.
    model::Railway* railway() const { return railway_; }

signals:
    // A new railway (or null); the previous one is deleted right after this signal.
    void railwayChanged(stellwerk::model::Railway* railway);

private:
    void sessionStarted(station::StationSession* session);
    void configurationLoaded(const station::StartupResult& result);
    void connectionStateChanged();
    void replace(model::Railway* railway);

    connection::StationConnection& connection_;
    model::Railway* railway_ = nullptr;
};

} // namespace stellwerk::ui
