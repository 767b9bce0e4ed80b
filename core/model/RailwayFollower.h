#pragma once

#include <QList>
#include <QMetaObject>
#include <QString>
#include <functional>
#include <vector>

namespace stellwerk::model {

class Railway;

// The railway's changes a server in front of it (the Z21 and WiThrottle servers) follows: connected together
// to the railway it serves and let go together when it turns to another, so every server hears the same.
class RailwayFollower {
public:
    // What the server is told; a function left empty is not connected.
    struct Changes {
        std::function<void()> loaded;
        // Locomotives changed, or the station acknowledged a command to one.
        std::function<void(const QList<quint32>& locIds)> locomotives;
        std::function<void(const QList<qint64>& keyboardNumbers)> accessories;
        std::function<void(const QList<qint64>& keyboardNumbers)> addresses;
        std::function<void()> routeFinished;
        // The track power changed, or whether the station's state is reported.
        std::function<void()> power;
        std::function<void(quint32 locId, const QString& from, const QString& to)> takenOver;
        // The railway is being destroyed.
        std::function<void()> gone;
    };

    explicit RailwayFollower(Changes changes);
    ~RailwayFollower();
    RailwayFollower(const RailwayFollower&) = delete;
    RailwayFollower& operator=(const RailwayFollower&) = delete;

    // Follows `railway` (null: none) instead of the one before.
    void follow(Railway* railway);

private:
    void letGo();

    Changes changes_;
    std::vector<QMetaObject::Connection> connections_;
};

} // namespace stellwerk::model
