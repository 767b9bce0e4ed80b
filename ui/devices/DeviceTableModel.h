#pragma once

#include <QAbstractTableModel>
#include <QPointer>
#include <QString>
#include <cstdint>
#include <vector>

namespace stellwerk::connection {
class ConnectionDevices;
}

namespace stellwerk::ui {

// The devices of the current connection as rows: the RO modules the connection was given (state, or why
// it has no session; ids, bus) and the OpenRailCAN devices the central found (UID, state, type, bus id).
class DeviceTableModel final : public QAbstractTableModel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(DeviceTableModel)

public:
    enum Column { Name, State, Kind, Address, ColumnCount };
    // What a row stands for: an OpenRailCAN device by UID, or an RO module by name.
    struct Row {
        bool orc = false;
        std::uint32_t uid = 0;
        QString module;
        friend bool operator==(const Row&, const Row&) = default;
    };

    explicit DeviceTableModel(QObject* parent = nullptr);

    void setDevices(connection::ConnectionDevices* devices);
    // Reads the devices again (a session came or went, a device changed).
    void refresh();
    const std::vector<Row>& rows() const { return m_rows; }
    // The row of this module or device, or -1.
    int rowOf(const Row& row) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // "decoder", "encoder", ... for an OpenRailCAN device type (001 §CAN-ID, bits 27-29).
    static QString orcTypeName(std::uint8_t type);

private:
    QString orcText(std::uint32_t uid, int column) const;
    QString moduleText(const QString& name, int column) const;
    QString moduleState(const QString& name) const;

    QPointer<connection::ConnectionDevices> m_devices;
    std::vector<Row> m_rows;
};

} // namespace stellwerk::ui
