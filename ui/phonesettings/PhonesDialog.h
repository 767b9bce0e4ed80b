#pragma once

#include "phones/PhoneSettings.h"

#include <QDialog>
#include <optional>

class QCheckBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace stellwerk::phones {
class PhoneServers;
}

namespace stellwerk::ui {

// Station → Phones…: the Z21 and WiThrottle servers switched on or off, where each listens (every network
// interface or one address, and the port) and which phones may connect. OK applies the choice at once (the
// servers restart) and keeps it; a server that cannot start says why and the dialog stays open.
class PhonesDialog final : public QDialog {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PhonesDialog)

public:
    PhonesDialog(phones::PhoneServers& servers, QWidget* parent = nullptr);

    // What the fields say; nullopt (and the problem shown) when an address cannot be read.
    std::optional<phones::PhoneSettings> chosen();

    void accept() override;

private:
    struct ServerFields {
        QCheckBox* on = nullptr;
        QLineEdit* address = nullptr;
        QSpinBox* port = nullptr;
    };
    ServerFields addServer(const QString& name, const QString& title, bool on,
                           const phones::ListenAddress& listen);
    std::optional<phones::ListenAddress> listenOf(const ServerFields& fields);

    phones::PhoneServers& m_servers;
    ServerFields m_z21;
    ServerFields m_withrottle;
    QLineEdit* m_clients = nullptr;
    QLabel* m_problem = nullptr;
};

} // namespace stellwerk::ui
