#include "aftertrouble/AftermathMenu.h"

#include "aftertrouble/AftermathSettings.h"
#include "model/Railway.h"

#include <QActionGroup>
#include <QEvent>

namespace stellwerk::ui {

AftermathMenu::AftermathMenu(QWidget* parent)
    : QMenu(parent), m_bringBack(new QAction(this)), m_group(new QActionGroup(this)),
      m_restore(addAction(QString())), m_stop(addAction(QString())) {
    setObjectName(QStringLiteral("aftermathMenu"));
    m_bringBack->setObjectName(QStringLiteral("bringBackInStepAction"));
    m_bringBack->setEnabled(false);
    connect(m_bringBack, &QAction::triggered, this, &AftermathMenu::bringBackInStep);
    m_restore->setObjectName(QStringLiteral("aftermathRestore"));
    m_stop->setObjectName(QStringLiteral("aftermathStop"));
    for (QAction* action : {m_restore, m_stop}) {
        action->setCheckable(true);
        m_group->addAction(action);
    }
    (AftermathSettings::load() == model::Aftermath::StopLocomotives ? m_stop : m_restore)->setChecked(true);
    connect(m_restore, &QAction::triggered, this, [this] { choose(model::Aftermath::RestoreConfirmed); });
    connect(m_stop, &QAction::triggered, this, [this] { choose(model::Aftermath::StopLocomotives); });
    retranslate();
}

model::Aftermath AftermathMenu::aftermath() const {
    return m_stop->isChecked() ? model::Aftermath::StopLocomotives : model::Aftermath::RestoreConfirmed;
}

void AftermathMenu::setRailway(model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    m_bringBack->setEnabled(railway != nullptr);
    if (!railway)
        return;
    railway->setAftermath(aftermath());
    connect(railway, &model::Railway::backInStep, this, [this](int answered, int unanswered) {
        emit report(
            unanswered == 0
                ? tr("The layout is back in step: %n states read again.", nullptr, answered)
                : tr("The layout is back in step, but %n states got no answer.", nullptr, unanswered));
    });
}

void AftermathMenu::choose(model::Aftermath aftermath) {
    AftermathSettings::save(aftermath);
    if (m_railway)
        m_railway->setAftermath(aftermath);
}

void AftermathMenu::bringBackInStep() {
    if (!m_railway)
        return;
    m_railway->bringBackInStep();
    emit report(aftermath() == model::Aftermath::StopLocomotives
                    ? tr("Stopping every locomotive and reading every state again…")
                    : tr("Sending every locomotive its confirmed speed and reading every state again…"));
}

void AftermathMenu::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMenu::changeEvent(event);
}

void AftermathMenu::retranslate() {
    setTitle(tr("After a &failed command"));
    m_restore->setText(tr("&Bring back what the station last confirmed"));
    m_stop->setText(tr("&Stop every locomotive that had one"));
    m_bringBack->setText(tr("Bring the layout back in &step"));
    m_bringBack->setToolTip(tr("Sends every locomotive the speed the station last confirmed (or stops them "
                               "all, as chosen under After a failed command) and reads every state again"));
}

} // namespace stellwerk::ui
