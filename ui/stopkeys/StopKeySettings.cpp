#include "stopkeys/StopKeySettings.h"

#include "common/StellwerkSettings.h"

namespace stellwerk::ui {
namespace {

const QString stopKeyKey = QStringLiteral("ui/stopKey");

} // namespace

QList<Qt::Key> StopKeySettings::choices() {
    return {Qt::Key_F12,   Qt::Key_F11,        Qt::Key_F10,    Qt::Key_F9,
            Qt::Key_Pause, Qt::Key_ScrollLock, Qt::Key_unknown};
}

// Stored as its portable name ("F12"); "" is none; anything else falls back to the default.
Qt::Key StopKeySettings::load() {
    const QSettings settings = stellwerkSettings();
    if (!settings.contains(stopKeyKey))
        return Default;
    const QString name = settings.value(stopKeyKey).toString();
    if (name.isEmpty())
        return Qt::Key_unknown;
    const QKeySequence sequence = QKeySequence::fromString(name, QKeySequence::PortableText);
    const Qt::Key key = sequence.isEmpty() ? Qt::Key_unknown : sequence[0].key();
    return choices().contains(key) ? key : Default;
}

void StopKeySettings::save(Qt::Key key) {
    QSettings settings = stellwerkSettings();
    settings.setValue(stopKeyKey, key == Qt::Key_unknown
                                      ? QString()
                                      : QKeySequence(key).toString(QKeySequence::PortableText));
}

} // namespace stellwerk::ui
