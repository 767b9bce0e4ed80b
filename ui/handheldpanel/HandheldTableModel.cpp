#include "handheldpanel/HandheldTableModel.h"

#include <QBrush>
#include <QPalette>

namespace stellwerk::ui {

using mcanhandhelds::Handheld;
using mcanhandhelds::HandheldState;

HandheldTableModel::HandheldTableModel(QObject* parent) : QAbstractTableModel(parent) {
    m_flush.setSingleShot(true);
    m_flush.setInterval(100);
    connect(&m_flush, &QTimer::timeout, this, &HandheldTableModel::flush);
}

void HandheldTableModel::show(std::vector<Handheld> handhelds) {
    m_waiting = std::move(handhelds);
    m_hasWaiting = true;
    if (!m_flush.isActive())
        m_flush.start();
}

// The same handhelds in the same order change in place; anything else is a new list.
void HandheldTableModel::flush() {
    if (!m_hasWaiting)
        return;
    m_hasWaiting = false;
    const bool sameRows =
        m_waiting.size() == m_rows.size() &&
        std::equal(m_rows.begin(), m_rows.end(), m_waiting.begin(),
                   [](const Handheld& a, const Handheld& b) { return a.uid == b.uid && a.ours == b.ours; });
    if (!sameRows) {
        beginResetModel();
        m_rows = std::move(m_waiting);
        endResetModel();
        return;
    }
    m_rows = std::move(m_waiting);
    if (!m_rows.empty())
        emit dataChanged(index(0, 0), index(int(m_rows.size()) - 1, ColumnCount - 1));
}

const Handheld* HandheldTableModel::handheld(int row) const {
    return row >= 0 && row < int(m_rows.size()) ? &m_rows[std::size_t(row)] : nullptr;
}

int HandheldTableModel::rowOf(std::uint32_t uid) const {
    for (std::size_t row = 0; row < m_rows.size(); ++row)
        if (m_rows[row].uid == uid)
            return int(row);
    return -1;
}

int HandheldTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int HandheldTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QString HandheldTableModel::stateText(const Handheld& handheld) {
    switch (handheld.state) {
    case HandheldState::LoggingIn:
        return tr("logging in (stage %1 of 7)").arg(handheld.loginStage);
    case HandheldState::Upgrading:
        return tr("reading its locomotives");
    case HandheldState::Online:
        return handheld.ours ? tr("online") : tr("online at another master");
    case HandheldState::Silent:
        return handheld.ours ? tr("silent: %n poll(s) left", nullptr, handheld.silentPollsLeft)
                             : tr("silent");
    case HandheldState::Offline:
        return tr("offline");
    case HandheldState::FlashMode:
        return tr("in its boot loader");
    }
    return {};
}

QString HandheldTableModel::locoText(const Handheld& handheld) const {
    if (handheld.locoRefused)
        return tr("refused: somebody else drives it");
    if (!handheld.locoName.isEmpty())
        return handheld.locoName;
    if (handheld.loco && m_locoName)
        return m_locoName(*handheld.loco);
    return {};
}

QString HandheldTableModel::text(const Handheld& handheld, int column) const {
    const bool driving = handheld.loco.has_value() || !handheld.locoName.isEmpty();
    switch (column) {
    case Name:
        return handheld.name.isEmpty() ? QStringLiteral("MS1 %1").arg(handheld.uid, 8, 16, QLatin1Char('0'))
                                       : handheld.name;
    case Node:
        return handheld.slaveNode ? QString::number(handheld.slaveNode) : QString();
    case State:
        return stateText(handheld);
    case Locomotive:
        return locoText(handheld);
    case Speed:
        return driving
                   ? (handheld.forward ? QStringLiteral("%1 ▶") : QStringLiteral("◀ %1")).arg(handheld.speed)
                   : QString();
    case Functions: {
        QStringList on;
        for (int f = 0; f < 32; ++f)
            if (handheld.functions & (1u << f))
                on << QStringLiteral("F%1").arg(f);
        return driving ? on.join(QLatin1Char(' ')) : QString();
    }
    case Stack:
        return handheld.ours ? tr("%n locomotive(s)", nullptr, int(handheld.stack.size())) : QString();
    default:
        return {};
    }
}

QVariant HandheldTableModel::data(const QModelIndex& index, int role) const {
    const Handheld* shown = handheld(index.row());
    if (!shown)
        return {};
    if (role == Qt::DisplayRole)
        return text(*shown, index.column());
    if (role == Qt::ToolTipRole && index.column() == Name)
        return tr("UID %1").arg(shown->uid, 8, 16, QLatin1Char('0'));
    if (role == Qt::ToolTipRole && index.column() == Node && shown->slaveNode)
        return tr("Node %1; its master's node is %2").arg(shown->slaveNode).arg(shown->masterNode());
    if (role == Qt::ForegroundRole &&
        (shown->state == HandheldState::Offline || shown->state == HandheldState::Silent))
        return QBrush(QPalette().color(QPalette::Disabled, QPalette::Text));
    return {};
}

QVariant HandheldTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Name:
        return tr("Handheld");
    case Node:
        return tr("Node");
    case State:
        return tr("State");
    case Locomotive:
        return tr("Locomotive");
    case Speed:
        return tr("Speed");
    case Functions:
        return tr("Functions");
    case Stack:
        return tr("Stack");
    default:
        return {};
    }
}

} // namespace stellwerk::ui
