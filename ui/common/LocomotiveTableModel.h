#pragma once

#include "common/RowIndex.h"

#include <QAbstractTableModel>
#include <QPointer>

namespace stellwerk::model {
class Locomotive;
class Railway;
} // namespace stellwerk::model

namespace stellwerk::ui {

// The railway's locomotives as a read-only table: name, address, speed, direction and the functions
// that are on. It follows the railway's batched change signal: one dataChanged per batch, rows are
// inserted for locomotives that appear on the bus, and the model is reset only when the layout loads.
class LocomotiveTableModel final : public QAbstractTableModel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LocomotiveTableModel)

public:
    enum Column { Name, Address, Speed, Direction, Functions, ColumnCount };

    explicit LocomotiveTableModel(QObject* parent = nullptr);

    // Shows `railway` from now on (null: no rows). It may go away at any time.
    void setRailway(const model::Railway* railway);
    // The locomotive's Loc-ID in the row (for tests and later views).
    quint32 locomotiveId(int row) const { return rows_.key(row); }
    std::optional<int> rowOf(quint32 locomotive) const { return rows_.row(locomotive); }
    // Headers and texts in the current language.
    void retranslate();

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // "MM2 24", "MFX 1", "DCC 3": the protocol and the address the user knows.
    static QString addressText(const model::Locomotive& loco);
    // "40 %" of the top speed.
    static QString speedText(const model::Locomotive& loco);
    static QString directionText(const model::Locomotive& loco);
    // "F0 F4", or a dash when no function is on.
    static QString functionsText(const model::Locomotive& loco);

private:
    void reload();
    void update(const QList<quint32>& ids);
    void insertNew();
    QString text(const model::Locomotive& loco, int column) const;

    QPointer<const model::Railway> railway_;
    RowIndex<quint32> rows_;
};

} // namespace stellwerk::ui
