#pragma once

#include "station/StationUpdates.h"

#include <QList>
#include <QPointer>
#include <QWidget>
#include <optional>

class QGroupBox;
class QLabel;
class QTableView;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

class ContactTableModel;
class LocomotiveTableModel;
class PowerStatus;

// The "Layout" page: a read-only look at the railway as the station reports it — track power, every
// locomotive with its speed, direction and functions, and every feedback contact with its occupancy —
// so that a person sees at once that the layout is alive. Driving and the track plan come later.
class LayoutOverview final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LayoutOverview)

public:
    explicit LayoutOverview(QWidget* parent = nullptr);

    // Shows `railway` from now on (null: nothing connected). It may go away at any time.
    void setRailway(const model::Railway* railway);

    LocomotiveTableModel* locomotives() const { return locomotives_; }
    ContactTableModel* contacts() const { return contacts_; }
    QString powerText() const;

protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    QGroupBox* tableBox(QTableView* view, const QString& objectName);
    QTableView* tableView(const QString& objectName);
    void retranslate();
    void fitColumns();
    static void fitColumnsOf(QTableView& view);
    static int widestAllowed(QList<int> wanted, int room);

    QPointer<const model::Railway> railway_;
    LocomotiveTableModel* locomotives_;
    ContactTableModel* contacts_;
    PowerStatus* power_;
    QTableView* locomotiveView_;
    QTableView* contactView_;
    QGroupBox* locomotiveBox_ = nullptr;
    QGroupBox* contactBox_ = nullptr;
};

} // namespace stellwerk::ui
