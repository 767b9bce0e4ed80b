#include "common/LocomotiveTableModel.h"

#include "common/NotReported.h"
#include "model/Railway.h"

#include <QPalette>
#include <algorithm>

namespace stellwerk::ui {

LocomotiveTableModel::LocomotiveTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void LocomotiveTableModel::setRailway(const model::Railway* railway) {
    if (railway_)
        disconnect(railway_, nullptr, this, nullptr);
    railway_ = railway;
    if (railway_) {
        connect(railway_, &model::Railway::loaded, this, &LocomotiveTableModel::reload);
        connect(railway_, &model::Railway::locomotivesChanged, this, &LocomotiveTableModel::update);
        connect(railway_, &model::Railway::stateReportedChanged, this, &LocomotiveTableModel::retranslate);
        connect(railway_, &QObject::destroyed, this, [this] { setRailway(nullptr); });
    }
    reload();
}

// The layout (re)loaded: the rows may be others now.
void LocomotiveTableModel::reload() {
    beginResetModel();
    rows_.reset(railway_ ? railway_->state().locomotives().keys() : std::vector<quint32>{});
    endResetModel();
}

// One batch: rows for locomotives seen for the first time, then one dataChanged over the changed rows.
void LocomotiveTableModel::update(const QList<quint32>& ids) {
    insertNew();
    int first = rowCount(), last = -1;
    for (const quint32 id : ids)
        if (const std::optional<int> row = rows_.row(id)) {
            first = std::min(first, *row);
            last = std::max(last, *row);
        }
    if (last >= 0)
        emit dataChanged(index(first, 0), index(last, ColumnCount - 1), {Qt::DisplayRole});
}

void LocomotiveTableModel::insertNew() {
    if (!railway_)
        return;
    const std::vector<quint32>& keys = railway_->state().locomotives().keys();
    if (int(keys.size()) <= rows_.size())
        return;
    beginInsertRows({}, rows_.size(), int(keys.size()) - 1);
    for (std::size_t i = std::size_t(rows_.size()); i < keys.size(); ++i)
        rows_.append(keys[i]);
    endInsertRows();
}

void LocomotiveTableModel::retranslate() {
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1),
                         {Qt::DisplayRole, Qt::ForegroundRole, Qt::ToolTipRole});
}

int LocomotiveTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : rows_.size();
}

int LocomotiveTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant LocomotiveTableModel::data(const QModelIndex& index, int role) const {
    if (!railway_ || !index.isValid() || index.row() >= rows_.size())
        return {};
    const model::Locomotive* loco = railway_->locomotive(rows_.key(index.row()));
    if (!loco)
        return {};
    if (role == Qt::DisplayRole)
        return text(*loco, index.column());
    if (role == Qt::TextAlignmentRole && index.column() == Speed)
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    const bool state = index.column() == Speed || index.column() == Direction || index.column() == Functions;
    if (state && NotReported::applies(railway_)) { // the last state reported, greyed
        if (role == Qt::ForegroundRole)
            return QPalette().brush(QPalette::Disabled, QPalette::Text);
        if (role == Qt::ToolTipRole)
            return NotReported::reason();
    }
    return {};
}

QString LocomotiveTableModel::text(const model::Locomotive& loco, int column) const {
    switch (column) {
    case Name:
        return loco.displayName();
    case Address:
        return addressText(loco);
    case Speed:
        return NotReported::applies(railway_) ? tr("%1 (%2)").arg(speedText(loco), NotReported::word())
                                              : speedText(loco);
    case Direction:
        return directionText(loco);
    case Functions:
        return functionsText(loco);
    }
    return {};
}

QVariant LocomotiveTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Name:
        return tr("Locomotive");
    case Address:
        return tr("Address");
    case Speed:
        return tr("Speed");
    case Direction:
        return tr("Direction");
    case Functions:
        return tr("Functions on");
    }
    return {};
}

QString LocomotiveTableModel::addressText(const model::Locomotive& loco) {
    const std::string_view protocol = cs2::protocolName(loco.id().protocol());
    return QStringLiteral("%1 %2")
        .arg(QString::fromLatin1(protocol.data(), qsizetype(protocol.size())).toUpper())
        .arg(loco.id().address());
}

QString LocomotiveTableModel::speedText(const model::Locomotive& loco) {
    return tr("%1 %").arg(loco.speed() * 100 / model::Locomotive::MaxSpeed);
}

QString LocomotiveTableModel::directionText(const model::Locomotive& loco) {
    return loco.direction() == cs2::Direction::Backward ? tr("backward") : tr("forward");
}

QString LocomotiveTableModel::functionsText(const model::Locomotive& loco) {
    QStringList on;
    for (const model::LocomotiveFunction& function : loco.functions())
        if (function.on)
            on << QStringLiteral("F%1").arg(function.number);
    return on.isEmpty() ? QStringLiteral("–") : on.join(QLatin1Char(' '));
}

} // namespace stellwerk::ui
