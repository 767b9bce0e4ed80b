#include "stopkeys/StopKeyMenu.h"

#include "stopkeys/StopKeySettings.h"

#include <QActionGroup>
#include <QEvent>

namespace stellwerk::ui {

StopKeyMenu::StopKeyMenu(Qt::Key current, QWidget* parent) : QMenu(parent), m_group(new QActionGroup(this)) {
    setObjectName(QStringLiteral("stopKeyMenu"));
    for (const Qt::Key key : StopKeySettings::choices()) {
        QAction* action = addAction(QString());
        action->setCheckable(true);
        action->setChecked(key == current);
        action->setData(int(key));
        action->setObjectName(QStringLiteral("stopKey_%1").arg(int(key)));
        m_group->addAction(action);
        connect(action, &QAction::triggered, this, [this, key] { emit keyChosen(key); });
    }
    retranslate();
}

Qt::Key StopKeyMenu::current() const {
    const QAction* checked = m_group->checkedAction();
    return checked ? Qt::Key(checked->data().toInt()) : Qt::Key_unknown;
}

void StopKeyMenu::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMenu::changeEvent(event);
}

void StopKeyMenu::retranslate() {
    setTitle(tr("Extra STOP &key"));
    for (QAction* action : m_group->actions()) {
        const auto key = Qt::Key(action->data().toInt());
        action->setText(key == Qt::Key_unknown ? tr("None (Space only)")
                                               : QKeySequence(key).toString(QKeySequence::NativeText));
    }
}

} // namespace stellwerk::ui
