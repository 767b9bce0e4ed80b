#pragma once

#include "handheldpanel/ThrottleTableModel.h"

#include <QObject>
#include <QPointer>
#include <vector>

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

// The throttles that are neither the desk nor an MS1 handheld, read from the phone servers' clients and
// the railway's owner book (who drives what), and the one thing the panel does to them: let one go.
class OtherThrottles final : public QObject {
    Q_OBJECT

public:
    explicit OtherThrottles(QObject* parent = nullptr);

    // Either may be null (that server is off).
    void setServers(z21server::Z21Server* z21, withrottleserver::WiThrottleServer* withrottle);
    void setRailway(model::Railway* railway);

    std::vector<ThrottleRow> rows() const;
    // Lets the client go: its server forgets or closes it and stops its locomotives. False: not known.
    bool letGo(const QString& key);

signals:
    // A client came, went, or drives something else.
    void changed();

private:
    void addZ21(std::vector<ThrottleRow>& rows) const;
    void addWiThrottle(std::vector<ThrottleRow>& rows) const;
    void addOpenRailCan(std::vector<ThrottleRow>& rows) const;
    QStringList locomotives(const QString& throttle) const;

    QPointer<z21server::Z21Server> m_z21;
    QPointer<withrottleserver::WiThrottleServer> m_withrottle;
    QPointer<model::Railway> m_railway;
};

} // namespace stellwerk::ui
