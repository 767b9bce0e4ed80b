#include "EmergencyStopKeys.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
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

bool isStopKey(const QKeyEvent& key) {
    if (key.modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    if (key.key() == Qt::Key_Escape)
        return true;
    return key.key() == Qt::Key_Space && !typesText(QApplication::focusWidget());
}

} // namespace

EmergencyStopKeys::EmergencyStopKeys(QObject* parent) : QObject(parent) {
    qApp->installEventFilter(this);
}

EmergencyStopKeys::~EmergencyStopKeys() {
    qApp->removeEventFilter(this);
}

// Key presses reach the application filter once per widget they are offered to; only the first offer,
// to the focus widget (or the window without one), counts. Auto-repeats of a held key do not stop again.
bool EmergencyStopKeys::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::KeyPress)
        return false;
    auto* key = static_cast<QKeyEvent*>(event);
    if (key->isAutoRepeat() || !isStopKey(*key))
        return false;
    QWidget* focus = QApplication::focusWidget();
    if (watched != (focus ? static_cast<QObject*>(focus) : QApplication::activeWindow()))
        return false;
    emit stopRequested();
    return key->key() == Qt::Key_Space; // Space is used up; Escape still closes a dialog or a menu
}

} // namespace stellwerk::ui
