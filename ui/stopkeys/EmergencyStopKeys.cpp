#include "stopkeys/EmergencyStopKeys.h"

#include "stopkeys/StopKeySettings.h"

#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>

namespace stellwerk::ui {

namespace {

// A widget in which Space types a space.
bool typesText(const QWidget* widget) {
    if (!widget)
        return false;
    if (const auto* line = qobject_cast<const QLineEdit*>(widget))
        return !line->isReadOnly();
    if (const auto* text = qobject_cast<const QTextEdit*>(widget))
        return !text->isReadOnly();
    if (const auto* plain = qobject_cast<const QPlainTextEdit*>(widget))
        return !plain->isReadOnly();
    if (const auto* combo = qobject_cast<const QComboBox*>(widget))
        return combo->isEditable();
    return qobject_cast<const QAbstractSpinBox*>(widget) != nullptr;
}

// An editor a table opened in one of its cells (a child of the table's viewport): Escape there cancels
// the edit.
bool editsACell(const QWidget* widget) {
    for (const QWidget* w = widget ? widget->parentWidget() : nullptr; w; w = w->parentWidget())
        if (const auto* view = qobject_cast<const QAbstractItemView*>(w->parentWidget()))
            if (view->viewport() == w)
                return true;
    return false;
}

} // namespace

EmergencyStopKeys::EmergencyStopKeys(QWidget* window, QObject* parent)
    : QObject(parent), m_window(window), m_extraKey(StopKeySettings::Default) {
    qApp->installEventFilter(this);
}

EmergencyStopKeys::~EmergencyStopKeys() {
    qApp->removeEventFilter(this);
}

// The main window or one of its floating panels is active, and nothing of its own is open on top of it.
bool EmergencyStopKeys::escapeMayStop() const {
    if (QApplication::activePopupWidget() || QApplication::activeModalWidget())
        return false;
    const QWidget* active = QApplication::activeWindow();
    const bool mainWindow = active && (active == m_window || qobject_cast<const QDockWidget*>(active));
    return mainWindow && !editsACell(QApplication::focusWidget());
}

bool EmergencyStopKeys::isStopKey(const QKeyEvent& key) const {
    if (key.modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    if (m_extraKey != Qt::Key_unknown && key.key() == m_extraKey)
        return true;
    if (key.key() == Qt::Key_Escape)
        return escapeMayStop();
    return key.key() == Qt::Key_Space && !typesText(QApplication::focusWidget());
}

// Key presses reach the application filter once per widget they are offered to; only the first offer,
// to the focus widget (or the window without one), counts. Auto-repeats of a held key do not stop again.
bool EmergencyStopKeys::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::KeyPress)
        return false;
    auto* key = static_cast<QKeyEvent*>(event);
    QWidget* focus = QApplication::focusWidget();
    if (watched != (focus ? static_cast<QObject*>(focus) : QApplication::activeWindow()))
        return false;
    if (key->isAutoRepeat() || !isStopKey(*key))
        return false;
    emit stopRequested();
    return key->key() !=
           Qt::Key_Escape; // Space and the extra key are used up; Escape still reaches the widget
}

} // namespace stellwerk::ui
