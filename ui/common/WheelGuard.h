#pragma once

#include <QObject>

class QWidget;

namespace stellwerk::ui {

// Keeps a mouse wheel that only passes over a control panel from changing what its controls say: inside
// a guarded panel, pickers (combo boxes), sliders and spin boxes take the wheel only while they have the
// keyboard focus; otherwise the wheel goes on to the scroll area around them, as a user scrolling the panel
// expects. One filter on the application covers controls a panel adds later (a new throttle, a device's
// setting).
class WheelGuard final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(WheelGuard)

public:
    // Guards every control inside `panel`, now and later.
    static void guard(QWidget* panel);
    // True for a picker, slider or spin box inside a guarded panel.
    static bool guards(const QWidget* control);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    WheelGuard() = default;
    static void keepWheelFocus(QWidget* control);
};

} // namespace stellwerk::ui
