#pragma once

#include "cs2config/LocomotiveEditor.h"

#include <QAbstractTableModel>
#include <QPointer>
#include <QSize>
#include <optional>
#include <vector>

namespace stellwerk::ui {

// The locomotives of lokomotive.cs2 as the editor holds them, one row per named record: what the
// locomotive list of the Locomotives page shows (name, address, decoder, icon, keys with an icon).
class LocomotivePictureBook;

class LocomotiveFileModel final : public QAbstractTableModel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LocomotiveFileModel)

public:
    enum Column { Name, Address, Decoder, Icon, Functions, ColumnCount };

    explicit LocomotiveFileModel(QObject* parent = nullptr);

    // Shows the editor's locomotives again (after a load or an edit); null: no rows.
    void show(const cs2config::LocomotiveEditor* editor);
    // Where the Picture column's small pictures come from (null: names only).
    void setPictures(LocomotivePictureBook* pictures);
    static constexpr QSize PictureBox{60, 20};
    // The record index in the file of a row, and the row of a record index.
    std::size_t fileIndex(int row) const { return m_rows[std::size_t(row)]; }
    std::optional<int> rowOf(std::size_t fileIndex) const;
    void retranslate();

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    // A row is dragged as its locomotive (LocomotiveMime): onto a block of the plan it places the train.
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;

    // "MM2 (programmable)", "DCC", "mfx", in the user's language.
    static QString decoderText(cs2config::LocomotiveDecoder decoder);
    // "MM2 24", "DCC 3", "mfx SID 5".
    static QString addressText(const cs2config::Locomotive& locomotive);

private:
    QString text(const cs2config::Locomotive& locomotive, int column) const;

    const cs2config::LocomotiveEditor* m_editor = nullptr;
    QPointer<LocomotivePictureBook> m_pictures;
    std::vector<std::size_t> m_rows;
};

} // namespace stellwerk::ui
