#include "shell/Translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QtDebug>

namespace stellwerk::ui {

namespace {

// Where qt_add_translations() puts the compiled translations inside the resources of stellwerk-ui.
QString resourcePath(Language language) {
    return QStringLiteral(":/i18n/stellwerk_%1.qm").arg(languageCode(language));
}

// Replaces an installed translator; a destroyed QTranslator removes itself from the application.
void install(std::unique_ptr<QTranslator>& slot, std::unique_ptr<QTranslator> next) {
    if (next) {
        QCoreApplication::installTranslator(next.get());
    }
    slot = std::move(next);
}

} // namespace

bool Translations::select(Language language) {
    auto next = std::make_unique<QTranslator>();
    if (!next->load(resourcePath(language))) {
        qWarning().noquote() << QStringLiteral("Cannot load the translation %1; keeping \"%2\".")
                                    .arg(resourcePath(language), languageCode(m_current));
        return false;
    }
    install(m_stellwerk, std::move(next));
    selectQtTranslation(language);
    m_current = language;
    return true;
}

// Qt's own texts (standard buttons, context menus) come from the system's Qt translations, if installed.
void Translations::selectQtTranslation(Language language) {
    if (language == Language::English) {
        install(m_qt, nullptr);
        return;
    }
    auto next = std::make_unique<QTranslator>();
    const QString directory = QLibraryInfo::path(QLibraryInfo::TranslationsPath);
    if (!next->load(QStringLiteral("qtbase_") + languageCode(language), directory)) {
        next.reset();
    }
    install(m_qt, std::move(next));
}

} // namespace stellwerk::ui
