#include "shell/Language.h"

namespace stellwerk::ui {

QString languageCode(Language language) {
    switch (language) {
    case Language::German:
        return QStringLiteral("de");
    case Language::English:
        break;
    }
    return QStringLiteral("en");
}

std::optional<Language> languageFromCode(QStringView code) {
    if (code == u"en") {
        return Language::English;
    }
    if (code == u"de") {
        return Language::German;
    }
    return std::nullopt;
}

Language defaultLanguage(const QLocale& system) {
    return system.language() == QLocale::German ? Language::German : Language::English;
}

} // namespace stellwerk::ui
