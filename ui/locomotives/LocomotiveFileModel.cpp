#include "locomotives/LocomotiveFileModel.h"

#include "common/LocomotiveMime.h"
#include "common/LocomotivePictureBook.h"

#include <QMimeData>
#include <algorithm>

namespace stellwerk::ui {

using cs2config::LocomotiveDecoder;

LocomotiveFileModel::LocomotiveFileModel(QObject* parent) : QAbstractTableModel(parent) {}

void LocomotiveFileModel::show(const cs2config::LocomotiveEditor* editor) {
    beginResetModel();
    m_editor = editor;
    m_rows.clear();
    if (m_editor)
        for (std::size_t i = 0; i < m_editor->locomotives().size(); ++i)
            if (!m_editor->locomotives()[i].isEmpty())
                m_rows.push_back(i);
    endResetModel();
}

void LocomotiveFileModel::setPictures(LocomotivePictureBook* pictures) {
    if (m_pictures)
        m_pictures->disconnect(this);
    m_pictures = pictures;
    auto repaint = [this] {
        if (rowCount() > 0)
            emit dataChanged(index(0, Icon), index(rowCount() - 1, Icon),
                             {Qt::DecorationRole, Qt::ToolTipRole});
    };
    if (m_pictures)
        connect(m_pictures, &LocomotivePictureBook::changed, this, repaint);
    repaint();
}

std::optional<int> LocomotiveFileModel::rowOf(std::size_t fileIndex) const {
    for (std::size_t row = 0; row < m_rows.size(); ++row)
        if (m_rows[row] == fileIndex)
            return int(row);
    return std::nullopt;
}

void LocomotiveFileModel::retranslate() {
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1), {Qt::DisplayRole});
}

int LocomotiveFileModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int LocomotiveFileModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant LocomotiveFileModel::data(const QModelIndex& index, int role) const {
    if (!m_editor || !index.isValid() || index.row() >= rowCount())
        return {};
    const cs2config::Locomotive& locomotive = m_editor->locomotives()[fileIndex(index.row())];
    // With pictures, the Icon column shows the picture and names it in the tooltip: the names need the room.
    if (role == Qt::DisplayRole && !(m_pictures && index.column() == Icon))
        return text(locomotive, index.column());
    if (m_pictures && index.column() == Icon && role == Qt::DecorationRole)
        return m_pictures->picture(QString::fromStdString(locomotive.icon), PictureBox);
    if (m_pictures && index.column() == Icon && role == Qt::ToolTipRole)
        return m_pictures->describe(QString::fromStdString(locomotive.icon));
    if (m_pictures && index.column() == Icon && role == Qt::AccessibleTextRole)
        return text(locomotive, index.column());
    if (role == Qt::TextAlignmentRole && index.column() == Functions)
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QString LocomotiveFileModel::text(const cs2config::Locomotive& locomotive, int column) const {
    switch (column) {
    case Name:
        return QString::fromStdString(locomotive.name);
    case Address:
        return addressText(locomotive);
    case Decoder:
        return locomotive.decoder == LocomotiveDecoder::Unknown
                   ? QString::fromStdString(locomotive.decoderText)
                   : decoderText(locomotive.decoder);
    case Icon:
        return locomotive.icon.empty() ? QStringLiteral("–") : QString::fromStdString(locomotive.icon);
    case Functions: // keys with an icon: stations write a block for every key, used or not
        return QString::number(std::ranges::count_if(
            locomotive.functions, [](const cs2config::Function& f) { return f.icon != 0; }));
    }
    return {};
}

QVariant LocomotiveFileModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Name:
        return tr("Name");
    case Address:
        return tr("Address");
    case Decoder:
        return tr("Decoder");
    case Icon:
        return tr("Icon");
    case Functions:
        return tr("Functions");
    }
    return {};
}

QString LocomotiveFileModel::decoderText(LocomotiveDecoder decoder) {
    switch (decoder) {
    case LocomotiveDecoder::Mm2Prg:
        return tr("MM2 (programmable)");
    case LocomotiveDecoder::Mm2Dil8:
        return tr("MM2 (DIL switches)");
    case LocomotiveDecoder::MmPrg:
        return tr("MM (programmable)");
    case LocomotiveDecoder::Mmm2Lok:
        return tr("MM2 (mLD/mSD)");
    case LocomotiveDecoder::Dcc:
        return tr("DCC");
    case LocomotiveDecoder::Mfx:
        return tr("mfx");
    case LocomotiveDecoder::Sx1:
        return tr("SX1");
    case LocomotiveDecoder::None:
    case LocomotiveDecoder::Unknown:
        break;
    }
    return tr("none");
}

QString LocomotiveFileModel::addressText(const cs2config::Locomotive& locomotive) {
    const cs2config::LocomotiveSettings settings = cs2config::LocomotiveSettings::of(locomotive);
    switch (locomotive.decoder) {
    case LocomotiveDecoder::Dcc:
        return tr("DCC %1").arg(settings.address);
    case LocomotiveDecoder::Mfx:
        return tr("mfx SID %1").arg(settings.address);
    case LocomotiveDecoder::Sx1:
        return tr("SX1 %1").arg(settings.address);
    case LocomotiveDecoder::None:
    case LocomotiveDecoder::Unknown:
        return QString::number(settings.address);
    default:
        return tr("MM2 %1").arg(settings.address);
    }
}

Qt::ItemFlags LocomotiveFileModel::flags(const QModelIndex& index) const {
    const Qt::ItemFlags flags = QAbstractTableModel::flags(index);
    return index.isValid() ? flags | Qt::ItemIsDragEnabled : flags;
}

QStringList LocomotiveFileModel::mimeTypes() const {
    return {LocomotiveMime::Type};
}

QMimeData* LocomotiveFileModel::mimeData(const QModelIndexList& indexes) const {
    if (indexes.isEmpty() || !m_editor)
        return nullptr;
    const cs2config::Locomotive& locomotive = m_editor->locomotives()[fileIndex(indexes.front().row())];
    if (locomotive.uid == 0) // not on the station yet: nothing to place
        return nullptr;
    return LocomotiveMime::make(locomotive.uid, QString::fromStdString(locomotive.name));
}

} // namespace stellwerk::ui
