#pragma once

#include <QStringList>
#include <QTableView>

namespace stellwerk::ui {

// The bus monitor's table: a fixed-width font, columns as wide as what they show (the direction as wide as
// its text in the language in use), the Bus column only when there is more than one bus, and the newest
// row kept in view while the user is at the bottom (scrolling up to read stops that).
class BusMonitorTable final : public QTableView {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BusMonitorTable)

public:
    explicit BusMonitorTable(QAbstractItemModel* rows, QWidget* parent = nullptr);

    void setBusColumnShown(bool shown);
    // Makes the Bus column as wide as the longest of these names (within reason).
    void fitBusColumn(const QStringList& names);

protected:
    void changeEvent(QEvent* event) override;

private:
    void fitColumns();
    void followNewest();

    bool m_followNewest = true;
};

} // namespace stellwerk::ui
