#include "station/ConfigDownload.h"

#include "cs2/Codec.h"

#include <QTimer>

namespace stellwerk::station {

ConfigDownload::ConfigDownload(CommandTracker& tracker, HashSource ownHash, QObject* parent)
    : QObject(parent), tracker_(tracker), ownHash_(std::move(ownHash)), idleTimer_(new QTimer(this)) {
    idleTimer_->setSingleShot(true);
    connect(idleTimer_, &QTimer::timeout, this, &ConfigDownload::idleExpired);
    receiver_.onProgress([this](const cs2config::StreamProgress&) { progressDirty_ = true; });
}

void ConfigDownload::fetch(cs2config::ConfigRequest request, Done done) {
    queue_.push_back(Job{std::move(request), std::move(done)});
    if (!active_)
        startNext();
}

void ConfigDownload::startNext() {
    if (queue_.empty())
        return;
    active_ = std::move(queue_.front());
    queue_.pop_front();
    Job& job = *active_;
    job.hash = ownHash_();
    receiver_.finish();
    receiver_.expectFile(job.request.key(), job.hash);
    auto frames = job.request.frames(job.hash);
    const auto decoded = cs2::decode(frames.front());
    const auto key = decoded ? ackKeyOf(*decoded) : std::nullopt;
    job.command = tracker_.sendFrames(
        std::move(frames), key.value_or(AckKey{}), [this](const CommandResult& r) { requestAnswered(r); },
        policy_);
}

void ConfigDownload::requestAnswered(const CommandResult& result) {
    if (!active_)
        return;
    active_->command = 0;
    if (!result.succeeded()) {
        complete(QStringLiteral("%1: the station did not acknowledge the request (%2)")
                     .arg(QString::fromStdString(active_->request.key()),
                          QLatin1String(commandStatusName(result.status))));
        return;
    }
    active_->acknowledged = true;
    if (!receiver_.collecting())
        idleTimer_->start(idle_);
}

void ConfigDownload::feed(const can::CanFrame& frame) {
    if (!active_ || !isOurs(frame))
        return;
    Job& job = *active_;
    if (job.command != 0) { // the stream began: it answers the request even if the ack was lost
        tracker_.forget(job.command);
        job.command = 0;
        job.acknowledged = true;
    }
    idleTimer_->start(idle_);
    for (auto& outcome : receiver_.feed(frame)) {
        if (outcome)
            complete(std::move(*outcome));
        else
            complete(QStringLiteral("%1: %2").arg(QString::fromStdString(job.request.key()),
                                                  QString::fromStdString(outcome.error().message)));
        if (!active_)
            return;
    }
}

bool ConfigDownload::isOurs(const can::CanFrame& frame) const {
    // An MS2 answers with hash 0 (field notes); broadcasts (DLC 7 headers) are not answers to us.
    return (cs2::hash(frame) == active_->hash || cs2::hash(frame) == 0) && frame.dlc != 7;
}

void ConfigDownload::flushProgress() {
    if (!progressDirty_ || !active_)
        return;
    progressDirty_ = false;
    const auto now = receiver_.progress();
    emit progress(QString::fromStdString(active_->request.key()), qsizetype(now.received),
                  qsizetype(now.announced));
}

void ConfigDownload::idleExpired() {
    if (!active_)
        return;
    const auto now = receiver_.progress();
    const QString key = QString::fromStdString(active_->request.key());
    if (!receiver_.collecting())
        complete(QStringLiteral("%1: acknowledged, but no stream arrived within %2 ms")
                     .arg(key)
                     .arg(idle_.count()));
    else
        complete(QStringLiteral("%1: the stream stopped after %2 of %3 bytes; the file is dropped")
                     .arg(key)
                     .arg(now.received)
                     .arg(now.announced));
}

void ConfigDownload::complete(const DownloadResult& result) {
    idleTimer_->stop();
    if (result) {
        const auto size = qsizetype(result->length);
        emit progress(QString::fromStdString(active_->request.key()), size, size);
    }
    progressDirty_ = false;
    Job job = std::move(*active_);
    active_.reset();
    if (job.command != 0)
        tracker_.forget(job.command);
    receiver_.finish();
    if (job.done)
        job.done(result);
    if (!active_)
        startNext();
}

} // namespace stellwerk::station
