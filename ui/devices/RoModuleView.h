#pragma once

#include <QPointer>
#include <QString>
#include <QWidget>

class QLabel;
class QPushButton;

namespace stellwerk::romodule {
class RoModuleSession;
}
namespace stellwerk::connection {
struct RoModuleSettings;
}

namespace stellwerk::ui {

class SignalGrid;

// One RO module as the Devices panel shows it: what it is and whether it answers, its relays to switch one
// by one or all off (shown as the module confirmed them), its inputs live, and how the conversation went.
class RoModuleView final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(RoModuleView)

public:
    explicit RoModuleView(QWidget* parent = nullptr);

    // The module's settings and its session (null: none on this connection, `why` says so).
    void setModule(const connection::RoModuleSettings& settings, romodule::RoModuleSession* session,
                   const QString& why);
    SignalGrid& relays() const { return *m_relays; }
    SignalGrid& inputs() const { return *m_inputs; }
    QPushButton& allOff() const { return *m_allOff; }
    QString stateText() const;
    // How the conversation went: answers, repeats, timeouts, refusals, foreign and unreadable frames.
    QString countersText() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void attach(romodule::RoModuleSession* session);
    void update();
    void failed(const QString& why);
    void retranslate();

    QPointer<romodule::RoModuleSession> m_session;
    QString m_name;
    QString m_why;
    QLabel* m_title;
    QLabel* m_state;
    QLabel* m_relaysLabel;
    SignalGrid* m_relays;
    QPushButton* m_allOff;
    QLabel* m_inputsLabel;
    SignalGrid* m_inputs;
    QLabel* m_problem;
    QLabel* m_counters;
};

} // namespace stellwerk::ui
