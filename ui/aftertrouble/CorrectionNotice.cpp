#include "aftertrouble/CorrectionNotice.h"

#include "aftertrouble/CorrectionText.h"
#include "model/Railway.h"

#include <QEvent>
#include <QMenu>

namespace stellwerk::ui {

CorrectionNotice::CorrectionNotice(QWidget* parent) : QToolButton(parent), m_menu(new QMenu(this)) {
    setObjectName(QStringLiteral("correctionNotice"));
    setToolButtonStyle(Qt::ToolButtonTextOnly);
    setPopupMode(QToolButton::InstantPopup);
    setMenu(m_menu);
    // Amber, like a warning lamp: something happened that the person should know of.
    setStyleSheet(QStringLiteral("QToolButton#correctionNotice { background: #f2b233; color: #000000; "
                                 "border: 1px solid #9a6a00; border-radius: 3px; padding: 1px 6px; }"));
    connect(m_menu, &QMenu::aboutToShow, this, &CorrectionNotice::fillMenu);
    setVisible(false);
}

void CorrectionNotice::setRailway(model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    if (railway)
        connect(railway, &model::Railway::stateCorrected, this, &CorrectionNotice::add);
}

void CorrectionNotice::add(const model::Correction& correction) {
    m_entries.push_back({QTime::currentTime(), correction});
    refresh();
    emit corrected(sentence(m_entries.back()));
}

QString CorrectionNotice::sentence(const Entry& entry) const {
    return CorrectionText::of(entry.correction, m_railway);
}

QStringList CorrectionNotice::entries() const {
    QStringList sentences;
    for (const Entry& entry : m_entries)
        sentences << sentence(entry);
    return sentences;
}

void CorrectionNotice::dismiss() {
    m_entries.clear();
    refresh();
}

void CorrectionNotice::refresh() {
    setVisible(!m_entries.empty());
    setText(QStringLiteral("⚠ ") + tr("%n set back after trouble", nullptr, int(m_entries.size())));
    setToolTip(m_entries.empty()
                   ? QString()
                   : sentence(m_entries.back()) + QLatin1Char('\n') + tr("Click for the list."));
}

void CorrectionNotice::fillMenu() {
    m_menu->clear();
    for (const Entry& entry : m_entries)
        m_menu
            ->addAction(entry.time.toString(QStringLiteral("HH:mm:ss")) + QStringLiteral("  ") +
                        sentence(entry))
            ->setEnabled(false);
    m_menu->addSeparator();
    m_menu->addAction(tr("Dismiss"), this, &CorrectionNotice::dismiss)
        ->setObjectName(QStringLiteral("dismissCorrections"));
}

void CorrectionNotice::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QToolButton::changeEvent(event);
}

} // namespace stellwerk::ui
