#pragma once

#include "station/CommandTracker.h"

#include <QString>

namespace stellwerk::model {

// The sentence a person reads when a command was not carried out: what was asked and why it failed.
// `what` names the command in railway words ("BR 218: speed 500").
QString commandProblem(const QString& what, const station::CommandResult& result);
// Why a command failed, without what it was ("no answer from the station after 3 attempts").
QString failureReason(const station::CommandResult& result);

} // namespace stellwerk::model
