// The accessory and route intents of the Railway.

#include "model/CommandProblem.h"
#include "model/Commands.h"
#include "model/Railway.h"
#include "station/StationSession.h"

#include <QPointer>

namespace stellwerk::model {
namespace {

// Command 0x0B for one position: output on; the station switches it off after the article's switch
// time, or after its default time (document 4.1) when the file names none.
cs2::Message switchCommand(const Accessory& accessory, const AccessoryOutput& output) {
    std::optional<std::uint16_t> time10ms;
    if (const auto ms = accessory.switchTimeMs(); ms && *ms > 0)
        time10ms = std::uint16_t(std::min<std::int64_t>(*ms / 10, 0xFFFF));
    return commands::switchOutput(output.address, output.output, time10ms);
}

QString accessoryName(const Accessory& accessory) {
    return accessory.name().isEmpty() ? QStringLiteral("Accessory %1").arg(accessory.id()) : accessory.name();
}

} // namespace

void Railway::switchAccessory(std::int64_t id, int position) {
    switchForRoute(id, position, [this, id, position](const QString& failure) {
        if (!failure.isEmpty())
            emit problem(failure);
        emit switchingEnded(id, position, failure.isEmpty());
    });
}

void Railway::switchAddress(std::int64_t address, int position) {
    const auto wire = cs2::LocId::fromAddress(cs2::Protocol::Mm2Accessory,
                                              std::uint32_t(std::max<std::int64_t>(address, 0)));
    const QString output = position == 0   ? QStringLiteral("red")
                           : position == 1 ? QStringLiteral("green")
                                           : QStringLiteral("output %1").arg(position);
    const QString what = QStringLiteral("Address %1: %2").arg(address).arg(output);
    if (!wire || address < 1 || position < 0 || position > 1) {
        emit problem(
            QStringLiteral("%1 cannot be switched: there is no such MM2 address or output").arg(what));
        emit switchingEnded(address, position, false);
        return;
    }
    sendSwitching(address, position, commands::switchOutput(*wire, std::uint8_t(position)), what);
}

void Railway::sendSwitching(std::int64_t address, int position, const cs2::Message& command,
                            const QString& what) {
    QPointer<Railway> self(this);
    const CommandTarget target = CommandTarget::address(address);
    const std::optional<int> confirmed = reportedValue(target);
    session_.request(
        command, [self, address, position, target, confirmed, what](const station::CommandResult& result) {
            if (!self)
                return;
            self->recordOutcome(target, position, confirmed, result);
            if (!result.succeeded())
                emit self->problem(commandProblem(what, result));
            emit self->switchingEnded(address, position, result.succeeded());
        });
}

// Sends the switching and reports once: empty on acknowledgement, else a sentence saying what failed.
void Railway::switchForRoute(std::int64_t id, int position, std::function<void(const QString&)> done) {
    const Accessory* accessory = state_.accessories().find(id);
    if (!accessory) {
        done(QStringLiteral("Accessory %1 is not on the keyboard").arg(id));
        return;
    }
    const auto output = accessory->outputFor(position);
    const QString what = QStringLiteral("%1: position %2").arg(accessoryName(*accessory)).arg(position);
    if (!output) {
        done(QStringLiteral("%1 does not exist for a %2").arg(what, accessory->type()));
        return;
    }
    if (switcher_ && switcher_->drives(id)) {
        QPointer<Railway> self(this);
        switcher_->switchTo(id, position, [self, what, done = std::move(done)](const QString& failure) {
            if (self)
                done(failure.isEmpty() ? QString() : QStringLiteral("%1: %2").arg(what, failure));
        });
        return;
    }
    QPointer<Railway> self(this);
    const CommandTarget target = CommandTarget::accessory(id);
    const std::optional<int> confirmed = reportedValue(target);
    session_.request(switchCommand(*accessory, *output),
                     [self, what, target, position, confirmed,
                      done = std::move(done)](const station::CommandResult& result) {
                         if (!self)
                             return;
                         self->recordOutcome(target, position, confirmed, result);
                         done(result.succeeded() ? QString() : commandProblem(what, result));
                     });
}

bool Railway::isRouteSet(std::int64_t id) const {
    return RoutePlan::of(state_.routeFile(), id).standsIn([this](std::int64_t id) -> std::optional<int> {
        const Accessory* accessory = this->accessory(id);
        if (!accessory || !accessory->isPositionReported() || accessory->position() < 0)
            return std::nullopt;
        return accessory->position();
    });
}

bool Railway::runRoute(std::int64_t id) {
    Route* route = state_.routes().find(id);
    if (!route || route->running()) {
        emit problem(route ? QStringLiteral("Route %1 is already running").arg(route->name())
                           : QStringLiteral("Route %1 does not exist").arg(id));
        return false;
    }
    RoutePlan plan = RoutePlan::of(state_.routeFile(), id);
    if (!plan.valid()) {
        emit problem(QStringLiteral("Route %1 cannot run: %2").arg(route->name(), plan.error));
        return false;
    }
    auto* runner = new RouteRunner(
        std::move(plan), [this](std::int64_t a, int p, auto done) { switchForRoute(a, p, std::move(done)); },
        this);
    connect(runner, &RouteRunner::progressed, this, &Railway::routeProgressed);
    connect(runner, &RouteRunner::finished, this, [this](qint64 r) {
        routeEnded(r);
        emit routeFinished(r);
    });
    connect(runner, &RouteRunner::failed, this, [this](qint64 r, const QString& message) {
        routeEnded(r);
        const Route* failed = state_.routes().find(r);
        emit routeFailed(r, message);
        emit problem(QStringLiteral("Route %1 stopped: %2")
                         .arg(failed ? failed->name() : QString::number(r), message));
    });
    runners_[id] = runner;
    route->setRunning(true);
    emit routeStarted(id);
    runner->start();
    return true;
}

void Railway::cancelRoute(std::int64_t id) {
    if (const auto it = runners_.find(id); it != runners_.end())
        it->second->cancel();
}

void Railway::routeEnded(std::int64_t id) {
    if (Route* route = state_.routes().find(id))
        route->setRunning(false);
    if (const auto it = runners_.find(id); it != runners_.end()) {
        it->second->deleteLater();
        runners_.erase(it);
    }
}

} // namespace stellwerk::model
