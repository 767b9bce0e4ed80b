#pragma once

#include <QAbstractTableModel>
#include <QDateTime>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <vector>

namespace stellwerk::ui {

// One throttle that is not the desk and no MS1: an OpenRailCAN throttle, a Z21 client or a WiThrottle
// client, as the Throttles panel lists it.
struct ThrottleRow {
    enum class Kind : std::uint8_t { OpenRailCan, Z21, WiThrottle };
    Kind kind = Kind::Z21;
    QString key;     // the name the owner book and the server know it by ("z21 127.0.0.1:61234")
    QString address; // ip:port, or the bus for OpenRailCAN throttles
    QString name;    // the device name a WiThrottle client gave; a Z21 client has none: its address
    QStringList locomotives;
    QDateTime lastAt; // invalid: nothing heard yet (or not known)
    QString lastText;
    bool canDisconnect = false;

    bool operator==(const ThrottleRow&) const = default;
};

// The other throttles as a table: kind, address, name, the locomotives each drives and its last message.
class ThrottleTableModel final : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { Kind, Address, Name, Locomotives, LastMessage, ColumnCount };

    explicit ThrottleTableModel(QObject* parent = nullptr);

    // Shows these rows; a row whose key stays keeps its place (only changed cells are told).
    void show(std::vector<ThrottleRow> rows);
    const ThrottleRow* row(int index) const;
    int rowOf(const QString& key) const;
    static QString kindText(ThrottleRow::Kind kind);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    void retranslate();

private:
    QString text(const ThrottleRow& row, int column) const;
    bool sameKeys(const std::vector<ThrottleRow>& rows) const;

    std::vector<ThrottleRow> m_rows;
};

} // namespace stellwerk::ui
