#pragma once

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QPushButton;
class QTableView;

namespace stellwerk::connection {
class ConnectionHandhelds;
}
namespace stellwerk::mcanhandhelds {
class HandheldMaster;
}
namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

class HandheldDetails;
class HandheldTableModel;

// The MS1 handhelds on the station's bus: whether Stellwerk is their master or only watches (and why), one
// row per handheld with its state and the locomotive it drives, and the selected one's name and stack.
class HandheldsPanel final : public QWidget {
    Q_OBJECT

public:
    explicit HandheldsPanel(QWidget* parent = nullptr);
    ~HandheldsPanel() override;

    // Shows the handhelds of the connection's `handhelds` face and sets Stellwerk's role there (null: none).
    void setHandhelds(connection::ConnectionHandhelds* handhelds);
    void setRailway(model::Railway* railway);
    HandheldTableModel& table() const { return *m_model; }
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
};

} // namespace stellwerk::ui
