#pragma once

#include "cs2config/LocomotiveEditor.h"
#include "model/Z21Addresses.h"

#include <QAbstractTableModel>
#include <QPointer>
#include <QSize>
#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::ui {

class LocomotivePictureBook;

// The locomotives of lokomotive.cs2 as the editor holds them, one row per named record: what the
// locomotive list of the Locomotives page shows (name, address, Z21 address, decoder, icon, keys with an
// icon). The Z21 address of an MM or mfx locomotive is edited here, in the book of Z21 addresses.

class LocomotiveFileModel final : public QAbstractTableModel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LocomotiveFileModel)

public:
    enum Column { Name, Address, Z21Address, Decoder, Icon, Functions, ColumnCount };

    explicit LocomotiveFileModel(QObject* parent = nullptr);

    // Shows the editor's locomotives again (after a load or an edit); null: no rows.
    void show(const cs2config::LocomotiveEditor* editor);
    // Where the Picture column's small pictures come from (null: names only).
    void setPictures(LocomotivePictureBook* pictures);
    static constexpr QSize PictureBox{60, 20};
    // The book the Z21 address column shows and edits (null: the column is empty); every MM and mfx
    // locomotive shown gets an address in it.
    void setZ21Addresses(model::Z21Addresses* book);
    bool showsZ21Addresses() const { return m_z21 != nullptr; }
    // The record index in the file of a row, and the row of a record index.
    std::size_t fileIndex(int row) const { return m_rows[std::size_t(row)]; }
    std::optional<int> rowOf(std::size_t fileIndex) const;
    void retranslate();

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    // Only the Z21 address of an MM or mfx locomotive is edited; a refused one stays as it was.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    // A row is dragged as its locomotive (LocomotiveMime): onto a block of the plan it places the train.
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;

    // "MM2 (programmable)", "DCC", "mfx", in the user's language.
    static QString decoderText(cs2config::LocomotiveDecoder decoder);
    // "MM2 24", "DCC 3", "mfx SID 5".
    static QString addressText(const cs2config::Locomotive& locomotive);

signals:
    // The book got a new address (it is to be saved): "'V 100 2023' has Z21 address 24 now."
    void z21AddressChanged(const QString& sentence);
    // An edited Z21 address was refused, with the reason for the user.
    void z21AddressRefused(const QString& sentence);
    // Addresses were given to locomotives that had none (the book is to be saved).
    void z21AddressesCovered();

private:
    QString text(const cs2config::Locomotive& locomotive, int column) const;

    using Refusal = model::Z21Addresses::Refusal;
    QString z21Text(const cs2config::Locomotive& locomotive) const;
    QString refusalText(Refusal refusal, uint address, const cs2config::Locomotive& locomotive) const;
    bool z21Editable(const cs2config::Locomotive& locomotive) const;
    std::vector<std::uint32_t> locIds() const;
    QString nameOf(std::uint32_t locId) const;
    void coverZ21Addresses();

    const cs2config::LocomotiveEditor* m_editor = nullptr;
    model::Z21Addresses* m_z21 = nullptr;
    QPointer<LocomotivePictureBook> m_pictures;
    std::vector<std::size_t> m_rows;
};

} // namespace stellwerk::ui
