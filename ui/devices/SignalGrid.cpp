#include "devices/SignalGrid.h"

#include "common/NotReported.h"
#include "common/StatusDot.h"

#include <QGridLayout>
#include <QToolButton>
#include <algorithm>

namespace stellwerk::ui {
namespace {

constexpr int PerRow = 8;
constexpr int MaximumCount = 32;

std::uint32_t bitOf(int number) {
    return std::uint32_t{1} << (number - 1);
}

} // namespace

SignalGrid::SignalGrid(Kind kind, QWidget* parent)
    : QWidget(parent), m_kind(kind), m_grid(new QGridLayout(this)) {
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setSpacing(4);
}

void SignalGrid::setCount(int count) {
    count = std::clamp(count, 0, MaximumCount);
    while (m_cells.size() > count)
        delete m_cells.takeLast();
    while (m_cells.size() < count) {
        const int number = int(m_cells.size()) + 1;
        auto* cell = new QToolButton(this);
        cell->setObjectName(QStringLiteral("cell%1").arg(number));
        cell->setText(QString::number(number));
        cell->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        cell->setMinimumWidth(cell->fontMetrics().horizontalAdvance(QStringLiteral("00…")) + 28);
        if (m_kind == Kind::Lamps) {
            cell->setAttribute(Qt::WA_TransparentForMouseEvents);
            cell->setFocusPolicy(Qt::NoFocus);
            cell->setAutoRaise(true);
        }
        connect(cell, &QToolButton::clicked, this, [this, number] { clicked(number); });
        m_grid->addWidget(cell, (number - 1) / PerRow, (number - 1) % PerRow);
        m_cells.append(cell);
    }
    m_waiting &= count >= MaximumCount ? ~std::uint32_t{0} : (std::uint32_t{1} << count) - 1;
    for (int number = 1; number <= count; ++number)
        paintCell(number);
}

void SignalGrid::setStates(std::optional<std::uint32_t> states) {
    if (states && m_states)
        m_waiting &= ~(*states ^ *m_states); // a confirmed change ends the wait for it
    m_states = states;
    if (!states)
        m_waiting = 0;
    for (int number = 1; number <= count(); ++number)
        paintCell(number);
}

void SignalGrid::setSwitchable(bool switchable) {
    m_switchable = switchable;
    for (int number = 1; number <= count(); ++number)
        paintCell(number);
}

void SignalGrid::stopWaiting() {
    m_waiting = 0;
    for (int number = 1; number <= count(); ++number)
        paintCell(number);
}

std::optional<bool> SignalGrid::state(int number) const {
    if (!m_states || number < 1 || number > count())
        return std::nullopt;
    return (*m_states & bitOf(number)) != 0;
}

bool SignalGrid::isWaiting(int number) const {
    return number >= 1 && number <= count() && (m_waiting & bitOf(number)) != 0;
}

QToolButton* SignalGrid::cell(int number) const {
    return number >= 1 && number <= count() ? m_cells.at(number - 1) : nullptr;
}

void SignalGrid::clicked(int number) {
    const std::optional<bool> now = state(number);
    if (m_kind != Kind::Switches || !now || !m_switchable || isWaiting(number))
        return;
    m_waiting |= bitOf(number);
    paintCell(number);
    emit switchRequested(number, !*now);
}

void SignalGrid::paintCell(int number) {
    QToolButton* cell = m_cells.at(number - 1);
    const std::optional<bool> on = state(number);
    const bool waiting = isWaiting(number);
    cell->setIcon(StatusDot::icon(!on ? StatusDot::Unknown : *on ? StatusDot::Running : StatusDot::Free));
    cell->setText(waiting ? QStringLiteral("%1…").arg(number) : QString::number(number));
    if (m_kind == Kind::Switches)
        cell->setEnabled(on.has_value() && m_switchable && !waiting);
    const QString what = !on ? NotReported::word() : *on ? tr("on") : tr("off");
    cell->setToolTip(waiting
                         ? tr("%1: %2, waiting for the device to confirm the change").arg(number).arg(what)
                         : tr("%1: %2").arg(number).arg(what));
}

} // namespace stellwerk::ui
