#pragma once

#include "common/RowIndex.h"
#include "model/FeedbackContact.h"

#include <QAbstractTableModel>
#include <QIcon>
#include <QPointer>

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// The railway's S88 feedback contacts as a read-only table: number, name, occupied (a red lamp) or free,
// and when that last changed; greyed "(not reported)" while the station is silent or reconnecting.
// Sorted by device and contact number; follows the railway's batched change signal with one dataChanged
// per batch and resets only when the layout loads.
class ContactTableModel final : public QAbstractTableModel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ContactTableModel)

public:
    enum Column { Number, Name, State, Locomotive, LastChange, ColumnCount };

    explicit ContactTableModel(QObject* parent = nullptr);

    // Shows `railway` from now on (null: no rows). It may go away at any time.
    void setRailway(const model::Railway* railway);
    model::ContactKey contactKey(int row) const { return rows_.key(row); }
    std::optional<int> rowOf(model::ContactKey key) const { return rows_.row(key); }
    // Headers and texts in the current language.
    void retranslate();

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // "7" for the station's own contacts, "2/7" (device/contact) for others.
    static QString numberText(const model::FeedbackContact& contact);
    static QString stateText(const model::FeedbackContact& contact);
    // The local time of the last change ("14:03:27"), empty before the first one.
    static QString lastChangeText(const model::FeedbackContact& contact);

private:
    void reload();
    void update(const QList<quint32>& keys);
    void insertNew();
    QVariant display(const model::FeedbackContact& contact, int column) const;
    QString occupantText(const model::FeedbackContact& contact) const;
    QVariant lamp(const model::FeedbackContact& contact) const;

    QPointer<const model::Railway> railway_;
    RowIndex<model::ContactKey> rows_;
    QIcon occupiedLamp_;
    QIcon freeLamp_;
    QIcon notReportedLamp_;
};

} // namespace stellwerk::ui
