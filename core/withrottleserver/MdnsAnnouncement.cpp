#include "withrottleserver/MdnsAnnouncement.h"

#include <QProcess>
#include <QStandardPaths>

namespace stellwerk::withrottleserver {

MdnsAnnouncement::MdnsAnnouncement(QStringList searchPaths, QObject* parent)
    : QObject(parent), searchPaths_(std::move(searchPaths)) {}

MdnsAnnouncement::~MdnsAnnouncement() {
    if (process_ && process_->state() != QProcess::NotRunning) {
        process_->terminate();
        if (!process_->waitForFinished(1000))
            process_->kill();
    }
}

bool MdnsAnnouncement::announce(const QString& name, quint16 port) {
    const QString program =
        QStandardPaths::findExecutable(QStringLiteral("avahi-publish-service"), searchPaths_);
    if (program.isEmpty()) {
        why_ = QStringLiteral("not announced over mDNS: avahi-publish-service not found");
        return false;
    }
    process_ = new QProcess(this);
    process_->setProcessChannelMode(QProcess::MergedChannels);
    process_->start(program, {name, QStringLiteral("_withrottle._tcp"), QString::number(port)});
    if (!process_->waitForStarted(2000)) {
        why_ = QStringLiteral("not announced over mDNS: %1").arg(process_->errorString());
        return false;
    }
    why_ = QStringLiteral("announced over mDNS as \"%1\" (_withrottle._tcp, port %2)").arg(name).arg(port);
    return true;
}

} // namespace stellwerk::withrottleserver
