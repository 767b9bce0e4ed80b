#pragma once

#include "shell/Language.h"

#include <QMenu>

class QActionGroup;

namespace stellwerk::ui {

// View → Language: one checkable entry per shipped language, each named in its own language so that
// a user who cannot read the current one still finds theirs.
class LanguageMenu final : public QMenu {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LanguageMenu)

public:
    LanguageMenu(Language current, QWidget* parent);

    void setCurrent(Language language);

signals:
    void languageChosen(stellwerk::ui::Language language);

protected:
    void changeEvent(QEvent* event) override;

private:
    void addLanguage(Language language, const QString& name, const QString& objectName);
    void retranslate();

    QActionGroup* m_group;
};

} // namespace stellwerk::ui
