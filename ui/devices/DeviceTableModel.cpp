#include "devices/DeviceTableModel.h"

#include "connection/ConnectionDevices.h"
#include "devices/HexText.h"
#include "orccentral/OrcSession.h"
#include "romodule/RoModuleSession.h"

namespace stellwerk::ui {
namespace {

using orccentral::OrcDevice;
using romodule::RoModuleSession;

const connection::RoModuleSettings* moduleSettings(const connection::ConnectionDevices& devices,
                                                   const QString& name) {
    return devices.active().roModule(name);
}

} // namespace

DeviceTableModel::DeviceTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void DeviceTableModel::setDevices(connection::ConnectionDevices* devices) {
    m_devices = devices;
    refresh();
}

void DeviceTableModel::refresh() {
    std::vector<Row> rows;
    if (m_devices) {
        for (const connection::RoModuleSettings& module : m_devices->active().roModules)
            rows.push_back({false, 0, QString::fromStdString(module.profile.name)});
        if (const orccentral::OrcSession* orc = m_devices->orcSession())
            for (const OrcDevice& device : orc->devices())
                rows.push_back({true, device.uid, {}});
    }
    if (rows == m_rows) {
        if (!m_rows.empty())
            emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
        return;
    }
    beginResetModel();
    m_rows = std::move(rows);
    endResetModel();
}

int DeviceTableModel::rowOf(const Row& row) const {
    const auto found = std::find(m_rows.begin(), m_rows.end(), row);
    return found == m_rows.end() ? -1 : int(found - m_rows.begin());
}

int DeviceTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int DeviceTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant DeviceTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount() || role != Qt::DisplayRole || !m_devices)
        return {};
    const Row& row = m_rows[std::size_t(index.row())];
    return row.orc ? orcText(row.uid, index.column()) : moduleText(row.module, index.column());
}

QVariant DeviceTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Name:
        return tr("Device");
    case Kind:
        return tr("Kind");
    case Address:
        return tr("Address");
    case State:
        return tr("State");
    default:
        return {};
    }
}

QString DeviceTableModel::orcTypeName(std::uint8_t type) {
    switch (type) {
    case 0:
        return tr("booster / system device");
    case 1:
        return tr("throttle");
    case 2:
        return tr("decoder");
    case 3:
        return tr("encoder");
    case 4:
        return tr("legacy decoder");
    case 5:
        return tr("legacy encoder");
    default:
        return tr("type %1").arg(type);
    }
}

QString DeviceTableModel::orcText(std::uint32_t uid, int column) const {
    const orccentral::OrcSession* orc = m_devices->orcSession();
    const OrcDevice* device = orc ? orc->device(uid) : nullptr;
    if (!device)
        return column == State ? tr("gone") : QString();
    switch (column) {
    case Name:
        return hexText::of(uid, 8);
    case Kind:
        return tr("OpenRailCAN %1").arg(orcTypeName(device->type));
    case Address:
        return tr("bus id %1").arg(hexText::of(device->busId, 4));
    default:
        break;
    }
    switch (device->state) {
    case OrcDevice::State::Assigning:
        return tr("getting its bus id");
    case OrcDevice::State::Online:
        return tr("online");
    case OrcDevice::State::Offline:
        return tr("offline: misses its pings");
    case OrcDevice::State::Unassigned:
        return tr("refused: its bus id is taken");
    }
    return {};
}

QString DeviceTableModel::moduleText(const QString& name, int column) const {
    const connection::RoModuleSettings* settings = moduleSettings(*m_devices, name);
    if (!settings)
        return {};
    const ro::FrameIds& ids = settings->profile.ids;
    const int digits = ids.extended ? 8 : 3;
    switch (column) {
    case Name:
        return name;
    case Kind:
        return tr("RO module, %n relay(s), %1-bit", nullptr, settings->profile.outputs.count)
            .arg(ids.extended ? 29 : 11);
    case Address:
        return tr("bus %1: %2 / %3")
            .arg(settings->bus)
            .arg(hexText::of(ids.request, digits), hexText::of(ids.answer, digits));
    default:
        return moduleState(name);
    }
}

QString DeviceTableModel::moduleState(const QString& name) const {
    const RoModuleSession* session = m_devices->roModule(name);
    if (!session) {
        for (const QString& refusal : m_devices->refusals())
            if (refusal.contains(name))
                return tr("refused");
        return tr("bus not connected");
    }
    switch (session->state()) {
    case RoModuleSession::State::Starting:
        return tr("reading its relays");
    case RoModuleSession::State::Online:
        return tr("online");
    case RoModuleSession::State::Offline:
        return tr("offline: does not answer");
    }
    return {};
}

} // namespace stellwerk::ui
