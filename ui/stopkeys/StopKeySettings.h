#pragma once

#include <QKeySequence>
#include <QList>

namespace stellwerk::ui {

// The extra key that stops the layout besides Space and the STOP key (key `ui/stopKey`): one of a few
// keys that type nothing, F12 unless chosen otherwise, or none.
class StopKeySettings final {
public:
    static constexpr Qt::Key Default = Qt::Key_F12;

    // The keys one may choose from (Qt::Key_unknown: none).
    static QList<Qt::Key> choices();
    static Qt::Key load();
    static void save(Qt::Key key);
};

} // namespace stellwerk::ui
