#pragma once

#include "model/RoutePlan.h"

#include <QObject>
#include <QString>
#include <functional>

class QTimer;

namespace stellwerk::model {

// Switches one accessory and reports the outcome once: an empty string on success, else what went wrong.
using AccessorySwitcher = std::function<void(std::int64_t accessory, int position,
                                             std::function<void(const QString& problem)> done)>;

// Runs a route: waits each step's delay, switches its accessory and waits for the station's
// confirmation before the next step, so the steps happen in order. Stops at the first failure.
class RouteRunner final : public QObject {
    Q_OBJECT

public:
    RouteRunner(RoutePlan plan, AccessorySwitcher switcher, QObject* parent = nullptr);

    void start();
    // Stops before the next step; a switching already sent still completes on the track.
    void cancel();

    std::int64_t route() const { return plan_.route; }
    bool running() const { return running_; }
    int stepCount() const { return int(plan_.actions.size()); }
    int stepsDone() const { return next_; }

signals:
    void progressed(qint64 route, int stepsDone, int stepCount);
    void finished(qint64 route);
    void failed(qint64 route, const QString& message);

private:
    void scheduleNext();
    void switchNext();
    void stepDone(const QString& problem);
    void fail(const QString& message);

    RoutePlan plan_;
    AccessorySwitcher switcher_;
    QTimer* delay_;
    int next_ = 0;
    bool running_ = false;
};

} // namespace stellwerk::model
