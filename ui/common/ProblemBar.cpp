#include "common/ProblemBar.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QToolButton>

namespace stellwerk::ui {

namespace {

QToolButton* barButton(QWidget* parent, const char* name) {
    auto* button = new QToolButton(parent);
    button->setObjectName(QLatin1String(name));
    button->setAutoRaise(true);
    button->setCursor(Qt::PointingHandCursor);
    return button;
}

} // namespace

ProblemBar::ProblemBar(QWidget* parent) : QFrame(parent) {
    setObjectName(QStringLiteral("problemBar"));
    setAttribute(Qt::WA_StyledBackground);
    setTone(Tone::Error);
    m_label = new QLabel(this);
    m_label->setObjectName(QStringLiteral("problemText"));
    m_label->setTextFormat(Qt::PlainText);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_label->setWordWrap(true);
    // As wide as the bar allows: a long first line never widens the panel (it is cut while folded).
    m_label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_fold = barButton(this, "foldProblem");
    m_dismiss = barButton(this, "dismissProblem");
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 6, 4, 6);
    layout->addWidget(m_label, 1);
    layout->addWidget(m_fold, 0, Qt::AlignTop);
    layout->addWidget(m_dismiss, 0, Qt::AlignTop);
    connect(m_fold, &QToolButton::clicked, this, [this] { setFolded(!m_folded); });
    connect(m_dismiss, &QToolButton::clicked, this, &ProblemBar::dismiss);
    hide();
    retranslate();
}

void ProblemBar::setTone(Tone tone) {
    m_tone = tone;
    const bool error = tone == Tone::Error;
    setStyleSheet(QStringLiteral("stellwerk--ui--ProblemBar { background: %1; border-radius: 4px; }"
                                 " QLabel, QToolButton { color: %2; }"
                                 " QToolButton { font-weight: bold; border: none; padding: 2px 6px; }"
                                 " QToolButton:hover { background: %3; border-radius: 3px; }")
                      .arg(error ? QStringLiteral("#c82c2c") : QStringLiteral("#f2b233"),
                           error ? QStringLiteral("white") : QStringLiteral("black"),
                           error ? QStringLiteral("#a82020") : QStringLiteral("#d99a1e")));
}

void ProblemBar::setProblem(Describe describe) {
    m_describe = std::move(describe);
    m_text = m_describe ? m_describe() : QString();
    m_folded = m_text.count(QLatin1Char('\n')) >= UnfoldedLines;
    refresh();
    setVisible(!m_text.isEmpty());
}

QString ProblemBar::text() const {
    return isHidden() ? QString() : m_text;
}

QString ProblemBar::shownText() const {
    return m_label->text();
}

void ProblemBar::setFolded(bool folded) {
    m_folded = folded && hasMoreLines();
    refresh();
}

void ProblemBar::dismiss() {
    hide();
}

bool ProblemBar::hasMoreLines() const {
    return m_text.contains(QLatin1Char('\n'));
}

// Folded: the first line alone, cut to the bar's width, with a sign that there is more.
void ProblemBar::refresh() {
    m_fold->setVisible(hasMoreLines());
    retranslate();
    if (!m_folded) {
        m_label->setWordWrap(true);
        m_label->setText(m_text);
        return;
    }
    m_label->setWordWrap(false);
    const QString first = m_text.section(QLatin1Char('\n'), 0, 0) + QStringLiteral(" …");
    const int room = std::max(m_label->width(), m_label->fontMetrics().averageCharWidth() * 20);
    m_label->setText(m_label->fontMetrics().elidedText(first, Qt::ElideRight, room));
}

void ProblemBar::retranslate() {
    m_fold->setText(m_folded ? tr("Show all") : tr("Fold"));
    m_fold->setToolTip(m_folded ? tr("Show the whole message") : tr("Show only the first line"));
    m_dismiss->setText(QStringLiteral("✕"));
    m_dismiss->setToolTip(tr("Dismiss this message"));
    m_dismiss->setAccessibleName(tr("Dismiss"));
}

void ProblemBar::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange && m_describe) {
        m_text = m_describe();
        refresh();
    } else if (event->type() == QEvent::LanguageChange) {
        retranslate();
    }
    QFrame::changeEvent(event);
}

void ProblemBar::resizeEvent(QResizeEvent* event) {
    QFrame::resizeEvent(event);
    if (m_folded)
        refresh();
}

} // namespace stellwerk::ui
