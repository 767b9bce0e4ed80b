#include "aftertrouble/CorrectionNotice.h"

#include "aftertrouble/CorrectionText.h"
#include "model/Railway.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QToolButton>

namespace stellwerk::ui {

CorrectionNotice::CorrectionNotice(QWidget* parent)
    : QFrame(parent), m_sentence(new QLabel(this)), m_list(new QToolButton(this)), m_menu(new QMenu(this)),
      m_dismiss(new QPushButton(this)) {
    setObjectName(QStringLiteral("correctionNotice"));
    // Amber, like a warning lamp, with black text that reads on it in light and dark desktops.
    setStyleSheet(QStringLiteral("QFrame#correctionNotice { background: #f2b233; border: 1px solid #9a6a00; "
                                 "border-radius: 3px; } QFrame#correctionNotice QLabel { color: #000000; }"));
    // One line: a wrapped label would ask the toolbar for the height of several.
    m_sentence->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_sentence->setMinimumWidth(200);
    m_sentence->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_list->setObjectName(QStringLiteral("correctionList"));
    m_list->setPopupMode(QToolButton::InstantPopup);
    m_list->setMenu(m_menu);
    m_dismiss->setObjectName(QStringLiteral("dismissCorrections"));
    connect(m_dismiss, &QPushButton::clicked, this, &CorrectionNotice::dismiss);
    connect(m_menu, &QMenu::aboutToShow, this, &CorrectionNotice::fillMenu);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 2, 4, 2);
    layout->addWidget(m_sentence, 1);
    layout->addWidget(m_list);
    layout->addWidget(m_dismiss);
    refresh();
}

void CorrectionNotice::setRailway(model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    if (railway)
        connect(railway, &model::Railway::stateCorrected, this, &CorrectionNotice::add);
}

void CorrectionNotice::add(const model::Correction& correction) {
    const bool first = m_entries.empty();
    m_entries.push_back({QTime::currentTime(), correction});
    refresh();
    if (first)
        emit wanted(true);
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

QString CorrectionNotice::summary() const {
    return m_list->text();
}

QString CorrectionNotice::newest() const {
    return m_entries.empty() ? QString() : sentence(m_entries.back());
}

void CorrectionNotice::dismiss() {
    const bool had = !m_entries.empty();
    m_entries.clear();
    refresh();
    if (had)
        emit wanted(false);
}

void CorrectionNotice::refresh() {
    m_sentence->setText(newest());
    m_sentence->setToolTip(newest());
    m_list->setText(QStringLiteral("⚠ ") + tr("%n set back after trouble", nullptr, int(m_entries.size())));
    m_list->setToolTip(tr("Everything set back since the last Dismiss, with its time"));
    m_dismiss->setText(tr("Dismiss"));
    m_dismiss->setToolTip(tr("I have read it: hide this strip until something is set back again"));
}

void CorrectionNotice::fillMenu() {
    m_menu->clear();
    for (const Entry& entry : m_entries)
        m_menu->addAction(entry.time.toString(QStringLiteral("HH:mm:ss")) + QStringLiteral("  ") + sentence(entry))
            ->setEnabled(false);
}

void CorrectionNotice::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QFrame::changeEvent(event);
}

} // namespace stellwerk::ui
