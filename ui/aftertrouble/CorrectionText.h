#pragma once

#include "model/UnconfirmedCommands.h"

#include <QCoreApplication>
#include <QString>

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// One sentence for a person about what Stellwerk brought back after a command the station did not
// confirm: "BR 218: the station carried out a command late that had failed (speed 20 %); set back to 0 %."
class CorrectionText final {
    Q_DECLARE_TR_FUNCTIONS(CorrectionText)

public:
    static QString of(const model::Correction& correction, const model::Railway* railway);

private:
    static QString targetName(const model::CommandTarget& target, const model::Railway* railway);
    static QString value(const model::CommandTarget& target, int value);
};

} // namespace stellwerk::ui
