#pragma once

#include <QPointer>
#include <QString>
#include <QWidget>

class QLabel;
class QPushButton;
class QStackedWidget;
class QTableView;

namespace stellwerk::connection {
class ConnectionDevices;
}
namespace stellwerk::model {
class Railway;
class RailwayDevices;
} // namespace stellwerk::model

namespace stellwerk::ui {

class BindingsDialog;
class DeviceTableModel;
class OrcDeviceView;
class RoModuleDialog;
class RoModuleView;

// The devices beside the station (issue 15): the OpenRailCAN devices the central found and the RO modules
// of the connection with their state; the selected one's relays, outputs and inputs; adding, changing and
// removing RO modules (saved with the station settings) and binding device outputs and inputs to the
// layout's articles and contacts.
class DevicesPanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(DevicesPanel)

public:
    explicit DevicesPanel(QWidget* parent = nullptr);
    ~DevicesPanel() override;

    // Shows the devices of the connection's `devices` face and edits its settings (null: none).
    void setDevices(connection::ConnectionDevices* devices);
    void setRailway(model::Railway* railway);

    DeviceTableModel& table() const { return *m_model; }
    QTableView& view() const { return *m_view; }
    RoModuleView& moduleView() const { return *m_moduleView; }
    OrcDeviceView& orcView() const { return *m_orcView; }
    QString summaryText() const;
    QString noteText() const;
    // Opens the module dialog (empty name: a new module); its OK saves. Null without a connection.
    RoModuleDialog* editModule(const QString& name);
    // Removes the module from the saved settings (no question asked).
    void removeModule(const QString& name);
    // Opens the bindings dialog; its OK applies (and, for a real station, saves). Null without a railway.
    BindingsDialog* editBindings();
    void selectRow(int row);

protected:
    void changeEvent(QEvent* event) override;

private:
    void attachSessions();
    void refresh();
    void updateDetails();
    void updateButtons();
    QString selectedModule() const;
    bool onDemo() const;
    model::RailwayDevices* railwayDevices() const;
    void saveModule(const QString& oldName, const RoModuleDialog& dialog);
    void applyBindings(const BindingsDialog& dialog);
    void askRemove();
    void retranslate();

    QPointer<connection::ConnectionDevices> m_devices;
    QPointer<model::Railway> m_railway;
    QLabel* m_summary;
    QTableView* m_view;
    DeviceTableModel* m_model;
    QStackedWidget* m_details;
    QLabel* m_hint;
    RoModuleView* m_moduleView;
    OrcDeviceView* m_orcView;
    QPushButton* m_add;
    QPushButton* m_edit;
    QPushButton* m_remove;
    QPushButton* m_bindings;
    QLabel* m_note;
};

} // namespace stellwerk::ui
