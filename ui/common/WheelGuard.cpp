#include "common/WheelGuard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QPointer>
#include <QScrollBar>
#include <QWidget>

namespace stellwerk::ui {
namespace {

const char* const GuardedProperty = "stellwerkWheelGuarded";

// A control whose value a wheel changes; scroll bars are what the wheel is meant for.
bool isControl(const QWidget* widget) {
    return qobject_cast<const QComboBox*>(widget) || qobject_cast<const QAbstractSpinBox*>(widget) ||
           (qobject_cast<const QAbstractSlider*>(widget) && !qobject_cast<const QScrollBar*>(widget));
}

bool insideGuardedPanel(const QWidget* widget) {
    for (const QWidget* up = widget; up; up = up->parentWidget())
        if (up->property(GuardedProperty).toBool())
            return true;
    return false;
}

} // namespace

void WheelGuard::guard(QWidget* panel) {
    static QPointer<WheelGuard> filter; // one for the application, gone with it
    if (!filter) {
        filter = new WheelGuard;
        filter->setParent(QCoreApplication::instance());
        QCoreApplication::instance()->installEventFilter(filter);
    }
    panel->setProperty(GuardedProperty, true);
    for (QWidget* child : panel->findChildren<QWidget*>())
        if (isControl(child))
            keepWheelFocus(child);
}

bool WheelGuard::guards(const QWidget* control) {
    return control && isControl(control) && insideGuardedPanel(control);
}

// Qt gives a wheel-focus control the focus before it sees the wheel; without that bit a control gets focus
// only from a click or the Tab key.
void WheelGuard::keepWheelFocus(QWidget* control) {
    if ((control->focusPolicy() & Qt::WheelFocus) == Qt::WheelFocus)
        control->setFocusPolicy(Qt::StrongFocus);
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event) {
    const QEvent::Type type = event->type();
    if (type != QEvent::Wheel && type != QEvent::Polish && type != QEvent::Show)
        return false;
    auto* control = qobject_cast<QWidget*>(watched);
    if (!guards(control))
        return false;
    if (type != QEvent::Wheel) {
        keepWheelFocus(control); // a control the panel added later
        return false;
    }
    if (control->hasFocus())
        return false;
    // Ignored and filtered: Qt offers the wheel to the parents, up to the scroll area.
    event->ignore();
    return true;
}

} // namespace stellwerk::ui
