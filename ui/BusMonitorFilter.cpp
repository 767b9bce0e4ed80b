#include "BusMonitorFilter.h"

#include "BusMonitorModel.h"
#include "cs2/LocId.h"

#include <QStringList>

namespace stellwerk::ui {

BusMonitorFilter::BusMonitorFilter(QObject* parent) : QSortFilterProxyModel(parent) {
    setDynamicSortFilter(false);
}

void BusMonitorFilter::setCommand(const QString& name) {
    if (name == m_command)
        return;
    m_command = name;
    invalidateFilter();
}

void BusMonitorFilter::setLocId(std::optional<std::uint32_t> locId) {
    if (locId == m_locId)
        return;
    m_locId = locId;
    invalidateFilter();
}

void BusMonitorFilter::setText(const QString& text) {
    if (text == m_text)
        return;
    m_text = text;
    invalidateFilter();
}

std::optional<std::uint32_t> BusMonitorFilter::parseLocId(const QString& text) {
    const QStringList words = text.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    bool ok = false;
    if (words.size() == 1) {
        const QString& word = words.front();
        const bool hex = word.startsWith(QLatin1String("0x"), Qt::CaseInsensitive);
        const uint value = hex ? word.mid(2).toUInt(&ok, 16) : word.toUInt(&ok, 10);
        return ok ? std::optional<std::uint32_t>(value) : std::nullopt;
    }
    if (words.size() != 2)
        return std::nullopt;
    const auto protocol = cs2::protocolFromName(words[0].toLower().toStdString());
    const uint address = words[1].toUInt(&ok, 10);
    if (!protocol || !ok)
        return std::nullopt;
    const auto locId = cs2::LocId::fromAddress(*protocol, address);
    return locId ? std::optional<std::uint32_t>(locId->value()) : std::nullopt;
}

bool BusMonitorFilter::filterAcceptsRow(int row, const QModelIndex& parent) const {
    const QModelIndex index = sourceModel()->index(row, 0, parent);
    if (!m_command.isEmpty() && index.data(BusMonitorModel::CommandRole).toString() != m_command)
        return false;
    if (m_locId) {
        const QVariant locId = index.data(BusMonitorModel::LocIdRole);
        if (!locId.isValid() || locId.toUInt() != *m_locId)
            return false;
    }
    return m_text.isEmpty() ||
           index.data(BusMonitorModel::SearchTextRole).toString().contains(m_text, Qt::CaseInsensitive);
}

} // namespace stellwerk::ui
