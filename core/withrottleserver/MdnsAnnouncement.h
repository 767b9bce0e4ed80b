#pragma once

#include <QObject>
#include <QString>
#include <QStringList>

class QProcess;

namespace stellwerk::withrottleserver {

// Announces the WiThrottle server as `_withrottle._tcp` over mDNS, so that Engine Driver and WiThrottle list
// it by themselves, where the system has Avahi: `avahi-publish-service` runs as long as this object lives.
// Without it nothing is announced (no new dependency); the phone is then given the address by hand.
class MdnsAnnouncement final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MdnsAnnouncement)

public:
    // `searchPaths` empty: the PATH.
    explicit MdnsAnnouncement(QStringList searchPaths = {}, QObject* parent = nullptr);
    ~MdnsAnnouncement() override;

    // Starts announcing `name` on `port`; false when avahi-publish-service is not there (`why()` says so).
    bool announce(const QString& name, quint16 port);
    // A sentence for the log: what is announced, or why nothing is.
    const QString& why() const { return why_; }

private:
    QStringList searchPaths_;
    QProcess* process_ = nullptr;
    QString why_;
};

} // namespace stellwerk::withrottleserver
