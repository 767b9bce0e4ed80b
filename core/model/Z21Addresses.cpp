#include "model/Z21Addresses.h"

#include "cs2/LocId.h"

#include <QSettings>
#include <QStringList>

namespace stellwerk::model {
namespace {

const QString group = QStringLiteral("z21Addresses");
const QString entriesKey = QStringLiteral("locomotives");

bool isDcc(std::uint32_t locId) {
    return cs2::LocId(locId).protocol() == cs2::Protocol::Dcc;
}

} // namespace

bool Z21Addresses::isBooked(std::uint32_t locId) {
    const cs2::Protocol protocol = cs2::LocId(locId).protocol();
    return protocol == cs2::Protocol::Mm2 || protocol == cs2::Protocol::Mfx;
}

void Z21Addresses::cover(const std::vector<std::uint32_t>& locIds) {
    for (const std::uint32_t locId : locIds) {
        if (!isBooked(locId) || entries_.contains(locId))
            continue;
        const bool mm = cs2::LocId(locId).protocol() == cs2::Protocol::Mm2;
        const auto own = std::uint16_t(cs2::LocId(locId).address());
        if (mm && own >= First && !holderOf(own, locIds, locId))
            entries_[locId] = own;
        else if (const std::uint16_t free = firstFree(FirstForMfx, locIds))
            entries_[locId] = free;
    }
}

std::optional<std::uint16_t> Z21Addresses::addressOf(std::uint32_t locId) const {
    if (isDcc(locId))
        return std::uint16_t(cs2::LocId(locId).address());
    const auto it = entries_.find(locId);
    if (it == entries_.end())
        return std::nullopt;
    return it->second;
}

std::optional<std::uint32_t> Z21Addresses::locoAt(std::uint16_t address,
                                                  const std::vector<std::uint32_t>& locIds) const {
    return holderOf(address, locIds);
}

std::optional<std::uint32_t> Z21Addresses::holderOf(std::uint16_t address,
                                                    const std::vector<std::uint32_t>& locIds,
                                                    std::uint32_t locId) const {
    for (const std::uint32_t other : locIds)
        if (other != locId && addressOf(other) == address)
            return other;
    for (const auto& [other, booked] : entries_)
        if (other != locId && booked == address)
            return other;
    return std::nullopt;
}

Z21Addresses::Refusal Z21Addresses::assign(std::uint32_t locId, std::uint16_t address,
                                           const std::vector<std::uint32_t>& locIds) {
    if (isDcc(locId))
        return Refusal::DccKeepsItsAddress;
    if (address < First || address > Last)
        return Refusal::OutOfRange;
    if (holderOf(address, locIds, locId))
        return Refusal::Taken;
    entries_[locId] = address;
    return Refusal::None;
}

std::uint16_t Z21Addresses::firstFree(std::uint16_t from, const std::vector<std::uint32_t>& locIds) const {
    for (std::uint32_t address = from; address <= Last; ++address)
        if (!holderOf(std::uint16_t(address), locIds))
            return std::uint16_t(address);
    return 0;
}

Z21Addresses Z21Addresses::load(QSettings& settings) {
    Z21Addresses book;
    settings.beginGroup(group);
    for (const QString& line : settings.value(entriesKey).toStringList()) {
        const QStringList parts = line.split(QLatin1Char('='));
        bool idOk = false;
        bool addressOk = false;
        const std::uint32_t locId = parts.value(0).toUInt(&idOk, 0);
        const std::uint32_t address = parts.value(1).toUInt(&addressOk);
        if (parts.size() == 2 && idOk && addressOk && address <= Last)
            book.assign(locId, std::uint16_t(address), {});
    }
    settings.endGroup();
    return book;
}

void Z21Addresses::save(QSettings& settings) const {
    QStringList lines;
    for (const auto& [locId, address] : entries_)
        lines << QStringLiteral("0x%1=%2").arg(locId, 4, 16, QLatin1Char('0')).arg(address);
    settings.beginGroup(group);
    settings.setValue(entriesKey, lines);
    settings.endGroup();
}

} // namespace stellwerk::model
