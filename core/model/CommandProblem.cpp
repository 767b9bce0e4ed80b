#include "model/CommandProblem.h"

namespace stellwerk::model {

QString failureReason(const station::CommandResult& result) {
    using Status = station::CommandResult::Status;
    switch (result.status) {
    case Status::Acknowledged:
        return {};
    case Status::Rejected:
        return QStringLiteral("the station refused it");
    case Status::TimedOut:
        return QStringLiteral("no answer from the station after %1 %2")
            .arg(result.attempts)
            .arg(result.attempts == 1 ? QStringLiteral("attempt") : QStringLiteral("attempts"));
    case Status::NotSent:
        return QStringLiteral("not sent: the connection to the station is down");
    case Status::Cancelled:
        return QStringLiteral("cancelled");
    }
    return QStringLiteral("unknown failure");
}

QString commandProblem(const QString& what, const station::CommandResult& result) {
    return QStringLiteral("%1 was not carried out: %2").arg(what, failureReason(result));
}

} // namespace stellwerk::model
