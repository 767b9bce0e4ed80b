#include "connection/LocomotivePictures.h"

#include "cs2config/LocomotivePicture.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QNetworkAccessManager>
#include <QNetworkProxy>
#include <QNetworkReply>
#include <QNetworkRequest>
#include <QUrl>

namespace stellwerk::connection {

namespace picture = cs2config::picture;

namespace {

std::optional<QString> fileNameOf(const QString& icon) {
    const auto name = picture::fileName(icon.toStdString());
    if (!name)
        return std::nullopt;
    return QString::fromStdString(*name);
}

QString unusableName(const QString& icon) {
    return icon.isEmpty() ? QStringLiteral("the locomotive names no picture")
                          : QStringLiteral("\"%1\" names no usable picture file").arg(icon);
}

} // namespace

LocomotivePictures::LocomotivePictures(QObject* parent) : LocomotivePictures(Settings{}, parent) {}

LocomotivePictures::LocomotivePictures(Settings settings, QObject* parent)
    : QObject(parent), settings_(settings), network_(new QNetworkAccessManager(this)) {
    // A station is on the local network: never ask a proxy for it.
    network_->setProxy(QNetworkProxy::NoProxy);
}

LocomotivePictures::~LocomotivePictures() {
    for (const auto& [reply, name] : running_) {
        reply->disconnect(this);
        reply->abort();
    }
}

void LocomotivePictures::setStation(const QString& webAddress) {
    if (webAddress == station_)
        return;
    station_ = webAddress;
    forgetAll();
}

void LocomotivePictures::setFolder(const QString& iconsFolder) {
    if (iconsFolder == folder_)
        return;
    folder_ = iconsFolder;
    forgetAll();
}

void LocomotivePictures::forgetAll() {
    for (const auto& [reply, name] : running_) {
        reply->disconnect(this);
        reply->abort();
        reply->deleteLater();
    }
    running_.clear();
    waiting_.clear();
    entries_.clear();
    emit picturesChanged();
}

std::optional<QByteArray> LocomotivePictures::picture(const QString& icon) {
    const std::optional<QString> name = fileNameOf(icon);
    if (!name)
        return std::nullopt;
    Entry& entry = entries_[*name];
    const bool retry =
        entry.status == Status::Failed &&
        entry.failedAt.msecsTo(QDateTime::currentDateTimeUtc()) >= settings_.retryAfter.count();
    if (entry.status == Status::Unknown || retry)
        look(*name, entry);
    if (entry.status != Status::Present)
        return std::nullopt;
    return entry.bytes;
}

void LocomotivePictures::look(const QString& fileName, Entry& entry) {
    if (readFromFolder(fileName, entry))
        return;
    if (station_.isEmpty()) {
        entry = {};
        entry.status = Status::Missing;
        entry.reason = Reason::NoSource;
        entry.problem = QStringLiteral("no icons folder has %1 and no station to ask").arg(fileName);
        entry.source = folder_.isEmpty() ? QString() : QDir(folder_).filePath(fileName);
        return;
    }
    entry = {Status::Loading, Reason::None, {}, {}, {}, {}};
    waiting_.push_back(fileName);
    startFetches();
}

bool LocomotivePictures::readFromFolder(const QString& fileName, Entry& entry) const {
    if (folder_.isEmpty())
        return false;
    QFile file(QDir(folder_).filePath(fileName));
    if (!file.exists())
        return false;
    const QByteArray bytes = file.open(QIODevice::ReadOnly) ? file.read(picture::MaxBytes + 1) : QByteArray();
    const auto problem = picture::problem(std::string_view(bytes.constData(), std::size_t(bytes.size())));
    entry.source = file.fileName();
    entry.status = problem ? Status::Missing : Status::Present;
    entry.reason = problem ? Reason::NotAPicture : Reason::None;
    entry.bytes = problem ? QByteArray() : bytes;
    entry.problem =
        problem ? QStringLiteral("%1: %2").arg(file.fileName(), QString::fromStdString(*problem)) : QString();
    return true;
}

void LocomotivePictures::startFetches() {
    while (!waiting_.empty() && int(running_.size()) < settings_.parallel) {
        const QString name = waiting_.front();
        waiting_.pop_front();
        fetch(name);
    }
}

void LocomotivePictures::fetch(const QString& fileName) {
    QUrl url(station_);
    url.setPath(QStringLiteral("/icons/") + fileName);
    QNetworkRequest request(url);
    request.setTransferTimeout(int(settings_.timeout.count()));
    request.setAttribute(QNetworkRequest::RedirectPolicyAttribute, QNetworkRequest::ManualRedirectPolicy);
    QNetworkReply* reply = network_->get(request);
    running_.emplace(reply, fileName);
    entries_[fileName].source = url.toString(QUrl::FullyEncoded);
    // A picture larger than any station serves is not read to its end.
    connect(reply, &QNetworkReply::downloadProgress, this, [reply](qint64 received, qint64 total) {
        if (received > qint64(picture::MaxBytes) || total > qint64(picture::MaxBytes)) {
            reply->setProperty("tooLarge", true);
            reply->abort();
        }
    });
    connect(reply, &QNetworkReply::finished, this, [this, reply, fileName] { fetched(reply, fileName); });
}

void LocomotivePictures::fetched(QNetworkReply* reply, const QString& fileName) {
    running_.erase(reply);
    reply->deleteLater();
    const int httpStatus = reply->attribute(QNetworkRequest::HttpStatusCodeAttribute).toInt();
    if (reply->property("tooLarge").toBool())
        settle(
            fileName, Status::Missing, Reason::NotAPicture, {},
            QStringLiteral("the station's %1 is larger than %2 bytes").arg(fileName).arg(picture::MaxBytes));
    else if (httpStatus == 404)
        settle(fileName, Status::Missing, Reason::NotThere, {},
               QStringLiteral("the station has no picture %1").arg(fileName));
    else if (reply->error() != QNetworkReply::NoError || httpStatus != 200)
        settle(fileName, Status::Failed, Reason::Unreachable, {},
               QStringLiteral("%1 could not be fetched: %2")
                   .arg(fileName, httpStatus != 0 && reply->error() == QNetworkReply::NoError
                                      ? QStringLiteral("HTTP status %1").arg(httpStatus)
                                      : reply->errorString()));
    else {
        const QByteArray bytes = reply->readAll();
        const auto problem = picture::problem(std::string_view(bytes.constData(), std::size_t(bytes.size())));
        if (problem)
            settle(fileName, Status::Missing, Reason::NotAPicture, {},
                   QStringLiteral("the station's %1 is %2").arg(fileName, QString::fromStdString(*problem)));
        else
            settle(fileName, Status::Present, Reason::None, bytes, {});
    }
    startFetches();
}

void LocomotivePictures::settle(const QString& fileName, Status status, Reason reason, QByteArray bytes,
                                QString problem) {
    Entry& entry = entries_[fileName];
    entry.status = status;
    entry.reason = reason;
    entry.bytes = std::move(bytes);
    entry.problem = std::move(problem);
    entry.failedAt = status == Status::Failed ? QDateTime::currentDateTimeUtc() : QDateTime();
    emit picturesChanged();
}

void LocomotivePictures::retryFailed() {
    bool any = false;
    for (auto& [name, entry] : entries_)
        if (entry.status == Status::Failed) {
            entry.status = Status::Unknown;
            any = true;
        }
    if (any)
        emit picturesChanged();
}

const LocomotivePictures::Entry* LocomotivePictures::entryFor(const QString& icon) const {
    const std::optional<QString> name = fileNameOf(icon);
    if (!name)
        return nullptr;
    const auto entry = entries_.find(*name);
    return entry == entries_.end() ? nullptr : &entry->second;
}

LocomotivePictures::Status LocomotivePictures::status(const QString& icon) const {
    if (!fileNameOf(icon))
        return Status::Missing;
    const Entry* entry = entryFor(icon);
    return entry ? entry->status : Status::Unknown;
}

QString LocomotivePictures::problem(const QString& icon) const {
    if (!fileNameOf(icon))
        return unusableName(icon);
    const Entry* entry = entryFor(icon);
    return entry ? entry->problem : QString();
}

LocomotivePictures::Reason LocomotivePictures::reason(const QString& icon) const {
    if (!fileNameOf(icon))
        return Reason::NoName;
    const Entry* entry = entryFor(icon);
    return entry ? entry->reason : Reason::None;
}

QString LocomotivePictures::source(const QString& icon) const {
    const Entry* entry = entryFor(icon);
    return entry && entry->status == Status::Present ? entry->source : QString();
}

QString LocomotivePictures::lookedAt(const QString& icon) const {
    const Entry* entry = entryFor(icon);
    return entry ? entry->source : QString();
}

} // namespace stellwerk::connection
