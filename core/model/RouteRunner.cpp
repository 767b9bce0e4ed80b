#include "model/RouteRunner.h"

#include <QPointer>
#include <QTimer>

namespace stellwerk::model {

RouteRunner::RouteRunner(RoutePlan plan, AccessorySwitcher switcher, QObject* parent)
    : QObject(parent), plan_(std::move(plan)), switcher_(std::move(switcher)), delay_(new QTimer(this)) {
    delay_->setSingleShot(true);
    delay_->setTimerType(Qt::PreciseTimer);
    connect(delay_, &QTimer::timeout, this, &RouteRunner::switchNext);
}

void RouteRunner::start() {
    if (running_)
        return;
    if (!plan_.valid()) {
        fail(plan_.error);
        return;
    }
    running_ = true;
    next_ = 0;
    scheduleNext();
}

void RouteRunner::cancel() {
    if (!running_)
        return;
    delay_->stop();
    fail(QStringLiteral("cancelled after %1 of %2 steps").arg(next_).arg(stepCount()));
}

void RouteRunner::scheduleNext() {
    if (next_ >= stepCount()) {
        running_ = false;
        emit finished(plan_.route);
        return;
    }
    delay_->start(plan_.actions[std::size_t(next_)].delay);
}

void RouteRunner::switchNext() {
    const RouteAction& action = plan_.actions[std::size_t(next_)];
    QPointer<RouteRunner> self(this);
    const int step = next_;
    switcher_(action.accessory, action.position, [self, step](const QString& problem) {
        if (self && self->running_ && self->next_ == step)
            self->stepDone(problem);
    });
}

void RouteRunner::stepDone(const QString& problem) {
    if (!problem.isEmpty()) {
        const RouteAction& action = plan_.actions[std::size_t(next_)];
        fail(QStringLiteral("step %1 of %2 (accessory %3 to position %4): %5")
                 .arg(next_ + 1)
                 .arg(stepCount())
                 .arg(action.accessory)
                 .arg(action.position)
                 .arg(problem));
        return;
    }
    ++next_;
    emit progressed(plan_.route, next_, stepCount());
    scheduleNext();
}

void RouteRunner::fail(const QString& message) {
    running_ = false;
    emit failed(plan_.route, message);
}

} // namespace stellwerk::model
