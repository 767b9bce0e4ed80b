#include "shell/LanguageMenu.h"

#include <QActionGroup>
#include <QEvent>

namespace stellwerk::ui {

LanguageMenu::LanguageMenu(Language current, QWidget* parent)
    : QMenu(parent), m_group(new QActionGroup(this)) {
    setObjectName(QStringLiteral("languageMenu"));
    m_group->setExclusive(true);
    addLanguage(Language::English, QStringLiteral("English"), QStringLiteral("languageEnglish"));
    addLanguage(Language::German, QStringLiteral("Deutsch"), QStringLiteral("languageGerman"));
    setCurrent(current);
    retranslate();
}

void LanguageMenu::setCurrent(Language language) {
    for (QAction* action : m_group->actions()) {
        action->setChecked(action->data().toString() == languageCode(language));
    }
}

void LanguageMenu::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
    }
    QMenu::changeEvent(event);
}

void LanguageMenu::addLanguage(Language language, const QString& name, const QString& objectName) {
    QAction* action = addAction(name);
    action->setObjectName(objectName);
    action->setCheckable(true);
    action->setData(languageCode(language));
    m_group->addAction(action);
    connect(action, &QAction::triggered, this, [this, language] { emit languageChosen(language); });
}

void LanguageMenu::retranslate() {
    setTitle(tr("&Language"));
}

} // namespace stellwerk::ui
