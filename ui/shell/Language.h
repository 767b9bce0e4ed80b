#pragma once

#include <QLocale>
#include <QString>
#include <QStringView>
#include <optional>

namespace stellwerk::ui {

// The user interface languages Stellwerk ships, and the short codes that name them in settings and files.
enum class Language { English, German };

// "en" or "de": the code used in the settings file and in the translation file names.
QString languageCode(Language language);

// The language a code names, or nothing for a code Stellwerk has no translation for.
std::optional<Language> languageFromCode(QStringView code);

// The language to start in when the user has not chosen one: German on a German system, else English.
Language defaultLanguage(const QLocale& system);

} // namespace stellwerk::ui
