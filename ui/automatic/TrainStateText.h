#pragma once

#include "automation/Schedule.h"

#include <QCoreApplication>
#include <QString>
#include <cstdint>

namespace stellwerk::operation {
class Operation;
}

namespace stellwerk::ui {

// What the Automatic panel says of a train: its state in words (with the fault's sentence), whether that is
// trouble, and its schedule in one line.
class TrainStateText {
    Q_DECLARE_TR_FUNCTIONS(TrainStateText)

public:
    static QString state(const operation::Operation& operation, std::uint32_t locId);
    static bool trouble(const operation::Operation& operation, std::uint32_t locId);
    // "Gleis 2 (5 s) → ▸Block 3 (2 s), loop": ▸ marks the stop it runs to next.
    static QString schedule(const automation::Schedule& schedule);
};

} // namespace stellwerk::ui
