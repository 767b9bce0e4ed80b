#include "shell/LanguageSettings.h"

#include "common/StellwerkSettings.h"

#include <QtDebug>

namespace stellwerk::ui {

namespace {

const QString languageKey = QStringLiteral("ui/language");

} // namespace

Language LanguageSettings::load() {
    const QSettings settings = stellwerkSettings();
    const Language fallback = defaultLanguage(QLocale::system());
    if (!settings.contains(languageKey)) {
        return fallback;
    }
    const QString code = settings.value(languageKey).toString();
    if (const auto language = languageFromCode(code)) {
        return *language;
    }
    qWarning().noquote() << QStringLiteral("%1: unknown language \"%2\" in key %3; using \"%4\" instead.")
                                .arg(settings.fileName(), code, languageKey, languageCode(fallback));
    return fallback;
}

void LanguageSettings::save(Language language) {
    QSettings settings = stellwerkSettings();
    settings.setValue(languageKey, languageCode(language));
}

} // namespace stellwerk::ui
