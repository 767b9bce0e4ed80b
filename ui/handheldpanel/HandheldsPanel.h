#pragma once

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QPushButton;
class QTabWidget;
class QTableView;
class QTimer;

namespace stellwerk::connection {
class ConnectionHandhelds;
}
namespace stellwerk::mcanhandhelds {
class HandheldMaster;
}
namespace stellwerk::model {
class Railway;
}
namespace stellwerk::withrottleserver {
class WiThrottleServer;
}
namespace stellwerk::z21server {
class Z21Server;
}

namespace stellwerk::ui {

class HandheldDetails;
class HandheldTableModel;
class OtherThrottles;
class ThrottleTableModel;

// The Throttles panel: every throttle that is not the desk. The MS1 handhelds on the station's bus (whether
// Stellwerk is their master or only watches, and why; one row per handheld with its state and locomotive,
// the selected one's name and stack) and below them the other throttles: OpenRailCAN throttles and the
// phones of the Z21 and WiThrottle servers, each with its address, name, locomotives and last message; a
// phone can be disconnected.
class HandheldsPanel final : public QWidget {
    Q_OBJECT

public:
    explicit HandheldsPanel(QWidget* parent = nullptr);
    ~HandheldsPanel() override;

    // Shows the handhelds of the connection's `handhelds` face and sets Stellwerk's role there (null: none).
    void setHandhelds(connection::ConnectionHandhelds* handhelds);
    void setRailway(model::Railway* railway);
    // The servers whose clients are listed (either may be null: that server is off).
    void setPhoneServers(z21server::Z21Server* z21, withrottleserver::WiThrottleServer* withrottle);
    HandheldTableModel& table() const { return *m_model; }
    ThrottleTableModel& otherThrottles() const { return *m_others; }
    // What the line above the table says now.
    QString roleText() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void attachMaster();
    void refresh();
    void updateRole();
    void updateMasterChoice();
    void updateDetails();
    void updateChoices();
    void chooseRole(bool master);
    void retranslate();
    QWidget* makeOthers();
    void refreshOthers();
    void updateDisconnect();
    void updateTabs();
    void disconnectSelected();

    QPointer<connection::ConnectionHandhelds> m_handhelds;
    QPointer<mcanhandhelds::HandheldMaster> m_master;
    QPointer<model::Railway> m_railway;
    QLabel* m_role;
    QCheckBox* m_actAsMaster;
    QLabel* m_bootLoader;
    QPushButton* m_silence;
    QTableView* m_view;
    HandheldTableModel* m_model;
    HandheldDetails* m_details;
    OtherThrottles* m_otherSource;
    ThrottleTableModel* m_others;
    QLabel* m_othersTitle;
    QTableView* m_othersView;
    QPushButton* m_disconnect;
    QTimer* m_othersClock;
    QTabWidget* m_kinds;
};

} // namespace stellwerk::ui
