#pragma once

#include "shell/Language.h"

#include <QTranslator>
#include <memory>

namespace stellwerk::ui {

// Puts the embedded translation of one language into effect for the whole application; every widget then
// receives QEvent::LanguageChange and retranslates its own texts.
class Translations final {
public:
    Translations() = default;
    Q_DISABLE_COPY_MOVE(Translations)

    // Installs Stellwerk's translation for the language (and Qt's own, where the system has it).
    // Returns false, keeping the current language, when the embedded translation cannot be loaded.
    bool select(Language language);
    Language current() const { return m_current; }

private:
    void selectQtTranslation(Language language);

    std::unique_ptr<QTranslator> m_stellwerk;
    std::unique_ptr<QTranslator> m_qt;
    Language m_current = Language::English;
};

} // namespace stellwerk::ui
