#include "locomotives/LocomotiveFileModel.h"

#include "common/LocomotiveMime.h"
#include "common/LocomotivePictureBook.h"
#include "model/Z21Addresses.h"

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
    coverZ21Addresses();
}

void LocomotiveFileModel::setZ21Addresses(model::Z21Addresses* book) {
    m_z21 = book;
    coverZ21Addresses();
    if (rowCount() > 0)
        emit dataChanged(index(0, Z21Address), index(rowCount() - 1, Z21Address));
}

void LocomotiveFileModel::coverZ21Addresses() {
    if (!m_z21 || !m_editor)
        return;
    const std::size_t before = m_z21->entries().size();
    m_z21->cover(locIds());
    if (m_z21->entries().size() != before)
        emit z21AddressesCovered();
}

std::vector<std::uint32_t> LocomotiveFileModel::locIds() const {
    std::vector<std::uint32_t> ids;
    for (const std::size_t i : m_rows)
        if (const std::uint32_t uid = m_editor->locomotives()[i].uid)
            ids.push_back(uid);
    return ids;
}

QString LocomotiveFileModel::nameOf(std::uint32_t locId) const {
    for (const std::size_t i : m_rows)
        if (m_editor->locomotives()[i].uid == locId)
            return QString::fromStdString(m_editor->locomotives()[i].name);
    return {};
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
    if (role == Qt::EditRole && index.column() == Z21Address)
        return m_z21 ? QVariant(m_z21->addressOf(locomotive.uid).value_or(0)) : QVariant();
    if (role == Qt::ToolTipRole && index.column() == Z21Address && m_z21)
        return z21Editable(locomotive) ? tr("The address the Z21 app and WLANmaus use for this locomotive; "
                                            "double-click to change it")
                                       : tr("A DCC locomotive has its own address on the Z21 too");
    if (role == Qt::TextAlignmentRole && (index.column() == Functions || index.column() == Z21Address))
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QString LocomotiveFileModel::text(const cs2config::Locomotive& locomotive, int column) const {
    switch (column) {
    case Name:
        return QString::fromStdString(locomotive.name);
    case Address:
        return addressText(locomotive);
    case Z21Address:
        return z21Text(locomotive);
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
    case Z21Address:
        return tr("Z21 address");
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

QString LocomotiveFileModel::z21Text(const cs2config::Locomotive& locomotive) const {
    const std::optional<std::uint16_t> address = m_z21 ? m_z21->addressOf(locomotive.uid) : std::nullopt;
    return address ? QString::number(*address) : QStringLiteral("–");
}

bool LocomotiveFileModel::z21Editable(const cs2config::Locomotive& locomotive) const {
    return m_z21 && locomotive.uid != 0 && model::Z21Addresses::isBooked(locomotive.uid);
}

// Why an edited Z21 address was refused, and what the locomotive keeps.
QString LocomotiveFileModel::refusalText(Refusal refusal, uint address,
                                         const cs2config::Locomotive& locomotive) const {
    const QString name = QString::fromStdString(locomotive.name);
    if (refusal != Refusal::Taken)
        return tr("A Z21 address is a number from %1 to %2; '%3' keeps %4.")
            .arg(model::Z21Addresses::First)
            .arg(model::Z21Addresses::Last)
            .arg(name, z21Text(locomotive));
    const QString holder =
        nameOf(m_z21->holderOf(std::uint16_t(address), locIds(), locomotive.uid).value_or(0));
    if (holder.isEmpty())
        return tr("Z21 address %1 is kept for another locomotive; '%2' keeps %3.")
            .arg(address)
            .arg(name, z21Text(locomotive));
    return tr("'%1' already has Z21 address %2; '%3' keeps %4.")
        .arg(holder)
        .arg(address)
        .arg(name, z21Text(locomotive));
}

Qt::ItemFlags LocomotiveFileModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags flags = QAbstractTableModel::flags(index);
    if (!index.isValid())
        return flags;
    if (index.column() == Z21Address && m_editor && index.row() < rowCount() &&
        z21Editable(m_editor->locomotives()[fileIndex(index.row())]))
        flags |= Qt::ItemIsEditable;
    return flags | Qt::ItemIsDragEnabled;
}

bool LocomotiveFileModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || index.column() != Z21Address || !(flags(index) & Qt::ItemIsEditable))
        return false;
    const cs2config::Locomotive& locomotive = m_editor->locomotives()[fileIndex(index.row())];
    const QString name = QString::fromStdString(locomotive.name);
    bool number = false;
    const uint address = value.toString().trimmed().toUInt(&number);
    const Refusal refusal = !number || address > model::Z21Addresses::Last
                                ? Refusal::OutOfRange
                                : m_z21->assign(locomotive.uid, std::uint16_t(address), locIds());
    if (refusal == Refusal::None) {
        emit dataChanged(index, index);
        emit z21AddressChanged(tr("'%1' has Z21 address %2 now.").arg(name).arg(address));
        return true;
    }
    emit z21AddressRefused(refusalText(refusal, address, locomotive));
    return false;
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
