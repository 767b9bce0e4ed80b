#pragma once

#include "model/BlockStates.h"

#include <QCoreApplication>
#include <QString>

namespace stellwerk::ui {

// Words for the block and memory states other programs announce on the station's bus, for the plan's
// block names, tooltips and the route menu; "unknown" for every state the station's document does not name.
class AnnouncedStateText final {
    Q_DECLARE_TR_FUNCTIONS(AnnouncedStateText)

public:
    static QString of(model::AnnouncedMeaning meaning);
};

} // namespace stellwerk::ui
