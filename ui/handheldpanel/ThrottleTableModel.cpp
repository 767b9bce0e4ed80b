#include "handheldpanel/ThrottleTableModel.h"

#include <QLocale>
#include <algorithm>

namespace stellwerk::ui {

ThrottleTableModel::ThrottleTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void ThrottleTableModel::show(std::vector<ThrottleRow> rows) {
    if (!sameKeys(rows)) {
        beginResetModel();
        m_rows = std::move(rows);
        endResetModel();
        return;
    }
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i] == m_rows[i])
            continue;
        m_rows[i] = std::move(rows[i]);
        emit dataChanged(index(int(i), 0), index(int(i), ColumnCount - 1));
    }
}

bool ThrottleTableModel::sameKeys(const std::vector<ThrottleRow>& rows) const {
    return std::equal(rows.begin(), rows.end(), m_rows.begin(), m_rows.end(),
                      [](const ThrottleRow& a, const ThrottleRow& b) { return a.key == b.key; });
}

const ThrottleRow* ThrottleTableModel::row(int index) const {
    return index >= 0 && index < int(m_rows.size()) ? &m_rows[std::size_t(index)] : nullptr;
}

int ThrottleTableModel::rowOf(const QString& key) const {
    const auto it =
        std::find_if(m_rows.begin(), m_rows.end(), [&](const ThrottleRow& row) { return row.key == key; });
    return it == m_rows.end() ? -1 : int(it - m_rows.begin());
}

QString ThrottleTableModel::kindText(ThrottleRow::Kind kind) {
    switch (kind) {
    case ThrottleRow::Kind::OpenRailCan:
        return tr("OpenRailCAN throttle");
    case ThrottleRow::Kind::Z21:
        return tr("Z21 app or WLANmaus");
    case ThrottleRow::Kind::WiThrottle:
        return tr("WiThrottle or Engine Driver");
    }
    return {};
}

int ThrottleTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int ThrottleTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ThrottleTableModel::data(const QModelIndex& index, int role) const {
    const ThrottleRow* shown = row(index.row());
    if (!shown)
        return {};
    if (role == Qt::DisplayRole)
        return text(*shown, index.column());
    if (role == Qt::ToolTipRole && index.column() == LastMessage && shown->lastAt.isValid())
        return QLocale().toString(shown->lastAt, QLocale::LongFormat);
    return {};
}

QString ThrottleTableModel::text(const ThrottleRow& row, int column) const {
    switch (column) {
    case Kind:
        return kindText(row.kind);
    case Address:
        return row.address;
    case Name:
        return row.name;
    case Locomotives:
        return row.locomotives.isEmpty() ? tr("none") : row.locomotives.join(QStringLiteral(", "));
    case LastMessage:
        if (!row.lastAt.isValid())
            return row.lastText;
        return QStringLiteral("%1  %2").arg(row.lastAt.toString(QStringLiteral("HH:mm:ss")), row.lastText);
    default:
        return {};
    }
}

QVariant ThrottleTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Kind:
        return tr("Kind");
    case Address:
        return tr("Address");
    case Name:
        return tr("Name");
    case Locomotives:
        return tr("Drives");
    case LastMessage:
        return tr("Last message");
    default:
        return {};
    }
}

void ThrottleTableModel::retranslate() {
    if (!m_rows.empty())
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
}

} // namespace stellwerk::ui
