#pragma once

#include "connection/HandheldConnection.h"

#include <QObject>

namespace stellwerk::connection {

class StationLink;

// The handhelds' face of a connection, all the handhelds panel and the railway may see: the MS1 handhelds'
// master on the station's bus while connected, and whether Stellwerk answers the handhelds. The
// StationConnection owns it (handhelds()) and makes a master with each connection.
class ConnectionHandhelds final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ConnectionHandhelds)

public:
    explicit ConnectionHandhelds(HandheldSettings settings, QObject* parent = nullptr);
    ~ConnectionHandhelds() override;

    // The master while connected (only watching when it may not be the master), else null. Made with the
    // connection's session, gone with it.
    mcanhandhelds::HandheldMaster* master() const;
    // Whether Stellwerk answers the handhelds, from now on and for later connections.
    void setRole(HandheldRole role);
    HandheldRole role() const { return settings_.role; }

signals:
    // A connection brought a new master, or took it away: whoever follows one asks master() again.
    void masterReplaced();

private:
    friend class StationConnection;
    // Makes Stellwerk's part in the handhelds' conversation on the link's station bus (kept by the link).
    void open(StationLink& link);
    // The connection closed: its master goes with it.
    void release();

    HandheldSettings settings_;
    StationLink* link_ = nullptr;
};

} // namespace stellwerk::connection
