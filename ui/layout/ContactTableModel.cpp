#include "layout/ContactTableModel.h"

#include "common/NotReported.h"
#include "common/StatusDot.h"
#include "model/Railway.h"

#include <QPalette>
#include <algorithm>

namespace stellwerk::ui {

ContactTableModel::ContactTableModel(QObject* parent)
    : QAbstractTableModel(parent), occupiedLamp_(StatusDot::icon(StatusDot::Occupied)),
      freeLamp_(StatusDot::icon(StatusDot::Free)), notReportedLamp_(StatusDot::icon(StatusDot::Unknown)) {}

void ContactTableModel::setRailway(const model::Railway* railway) {
    if (railway_)
        disconnect(railway_, nullptr, this, nullptr);
    railway_ = railway;
    if (railway_) {
        connect(railway_, &model::Railway::loaded, this, &ContactTableModel::reload);
        connect(railway_, &model::Railway::contactsChanged, this, &ContactTableModel::update);
        connect(railway_, &model::Railway::stateReportedChanged, this, &ContactTableModel::retranslate);
        connect(railway_, &QObject::destroyed, this, [this] { setRailway(nullptr); });
    }
    reload();
}

// The layout (re)loaded: its contacts in device and contact order.
void ContactTableModel::reload() {
    beginResetModel();
    std::vector<model::ContactKey> keys;
    if (railway_)
        keys = railway_->state().contacts().keys();
    std::ranges::sort(keys);
    rows_.reset(std::move(keys));
    endResetModel();
}

// One batch: rows for contacts first heard of, then one dataChanged over the changed rows.
void ContactTableModel::update(const QList<quint32>& keys) {
    insertNew();
    int first = rowCount(), last = -1;
    for (const quint32 key : keys)
        if (const std::optional<int> row = rows_.row(key)) {
            first = std::min(first, *row);
            last = std::max(last, *row);
        }
    if (last >= 0)
        emit dataChanged(index(first, 0), index(last, ColumnCount - 1),
                         {Qt::DisplayRole, Qt::DecorationRole});
}

// Contacts that are not in the track plan but reported on the bus come at the end, in order of arrival.
void ContactTableModel::insertNew() {
    if (!railway_ || int(railway_->state().contacts().size()) <= rows_.size())
        return;
    std::vector<model::ContactKey> added;
    for (const model::ContactKey key : railway_->state().contacts().keys())
        if (!rows_.row(key))
            added.push_back(key);
    if (added.empty())
        return;
    beginInsertRows({}, rows_.size(), rows_.size() + int(added.size()) - 1);
    for (const model::ContactKey key : added)
        rows_.append(key);
    endInsertRows();
}

void ContactTableModel::retranslate() {
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1),
                         {Qt::DisplayRole, Qt::DecorationRole, Qt::ForegroundRole, Qt::ToolTipRole});
}

int ContactTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : rows_.size();
}

int ContactTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ContactTableModel::data(const QModelIndex& index, int role) const {
    if (!railway_ || !index.isValid() || index.row() >= rows_.size())
        return {};
    const model::FeedbackContact* contact = railway_->contact(rows_.key(index.row()));
    if (!contact)
        return {};
    if (role == Qt::DisplayRole)
        return display(*contact, index.column());
    if (role == Qt::DecorationRole && index.column() == State)
        return lamp(*contact);
    if (NotReported::applies(railway_) && index.column() == State) { // the last state, greyed
        if (role == Qt::ForegroundRole)
            return QPalette().brush(QPalette::Disabled, QPalette::Text);
        if (role == Qt::ToolTipRole)
            return NotReported::reason();
    }
    if (role == Qt::TextAlignmentRole && index.column() == Number)
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant ContactTableModel::display(const model::FeedbackContact& contact, int column) const {
    switch (column) {
    case Number:
        return numberText(contact);
    case Name:
        return contact.name();
    case State:
        return NotReported::applies(railway_) ? tr("%1 (%2)").arg(stateText(contact), NotReported::word())
                                              : stateText(contact);
    case Locomotive:
        return occupantText(contact);
    case LastChange:
        return lastChangeText(contact);
    }
    return {};
}

// The locomotive on an occupied contact, where the simulator or the user said which it is.
QString ContactTableModel::occupantText(const model::FeedbackContact& contact) const {
    const model::Locomotive* locomotive = railway_->locomotiveOn(contact);
    return locomotive ? locomotive->displayName() : QString();
}

QVariant ContactTableModel::lamp(const model::FeedbackContact& contact) const {
    if (!contact.known())
        return {};
    if (NotReported::applies(railway_))
        return notReportedLamp_;
    return contact.occupied() ? occupiedLamp_ : freeLamp_;
}

QVariant ContactTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Number:
        return tr("Contact");
    case Name:
        return tr("Name");
    case State:
        return tr("State");
    case Locomotive:
        return tr("Locomotive");
    case LastChange:
        return tr("Last change");
    }
    return {};
}

QString ContactTableModel::numberText(const model::FeedbackContact& contact) {
    if (contact.device() == 0)
        return QString::number(contact.contact());
    return QStringLiteral("%1/%2").arg(contact.device()).arg(contact.contact());
}

QString ContactTableModel::stateText(const model::FeedbackContact& contact) {
    if (!contact.known())
        return tr("unknown");
    return contact.occupied() ? tr("occupied") : tr("free");
}

QString ContactTableModel::lastChangeText(const model::FeedbackContact& contact) {
    if (!contact.lastChange().isValid())
        return {};
    return contact.lastChange().toLocalTime().time().toString(QStringLiteral("HH:mm:ss"));
}

} // namespace stellwerk::ui
