#pragma once

#include <QCoreApplication>
#include <QString>

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// The words every view uses for station state it cannot vouch for: while the station is silent or the
// connection is being made again (Railway::isStateReported() false), views show the last state the
// station reported greyed, and say so with these words.
class NotReported final {
    Q_DECLARE_TR_FUNCTIONS(NotReported)

public:
    // True while `railway` exists but its state is not what the station reports now.
    static bool applies(const model::Railway* railway);
    // "not reported", for a table cell or a short label.
    static QString word();
    // Why, and what the greyed state means; for tool tips.
    static QString reason();
};

} // namespace stellwerk::ui
