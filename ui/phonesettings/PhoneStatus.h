#pragma once

#include <QLabel>
#include <QPointer>

namespace stellwerk::phones {
class PhoneServers;
}

namespace stellwerk::ui {

// The status bar's "Phones: N" while a phone server runs (issue 35): how many phones and tablets are
// connected to the Z21 and WiThrottle servers together, the tooltip naming them; hidden while both are off.
class PhoneStatus final : public QLabel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PhoneStatus)

public:
    explicit PhoneStatus(QWidget* parent = nullptr);

    // The servers shown (null: none; the label hides). They must outlive this or be replaced first.
    void setPhoneServers(phones::PhoneServers* servers);

protected:
    void changeEvent(QEvent* event) override;

private:
    void refresh();

    QPointer<phones::PhoneServers> m_servers;
};

} // namespace stellwerk::ui
