#pragma once

#include "automation/StopReason.h"

#include <QCoreApplication>
#include <QString>

namespace stellwerk::ui {

// Why the automation stopped a train, in the user's language: the window's words for the core's
// StopReason (the command line prints the core's English sentence, which the English text here matches).
class StopReasonText {
    Q_DECLARE_TR_FUNCTIONS(StopReasonText)

public:
    static QString of(const automation::StopReason& reason);
};

} // namespace stellwerk::ui
