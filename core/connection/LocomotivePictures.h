#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QObject>
#include <QString>
#include <chrono>
#include <deque>
#include <map>
#include <optional>

class QNetworkAccessManager;
class QNetworkReply;

namespace stellwerk::connection {

// The locomotives' pictures, found once and kept: in the icons folder of the layout that is open, else
// on the station's web server (/icons/<name>.png). A fetch has a time limit and a size limit and at most
// two run at a time, so a slow or absent station never holds up the desk. What is not there or not a
// picture is remembered as missing with the reason; a fetch that failed because the station was away or
// slow is tried again when the station is back (retryFailed) or after a while.
class LocomotivePictures final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LocomotivePictures)

public:
    enum class Status { Unknown, Loading, Present, Missing, Failed };
    Q_ENUM(Status)
    // Why a picture is missing or failed, for a translated text.
    enum class Reason { None, NoName, NoSource, NotThere, NotAPicture, Unreachable };
    Q_ENUM(Reason)

    struct Settings {
        std::chrono::milliseconds timeout{5000};     // one fetch, from asking to the last byte
        std::chrono::milliseconds retryAfter{30000}; // a failed fetch is tried again after this
        int parallel = 2;
    };

    explicit LocomotivePictures(QObject* parent = nullptr);
    LocomotivePictures(Settings settings, QObject* parent = nullptr);
    ~LocomotivePictures() override;

    // The station's web server ("http://192.168.2.5", "http://127.0.0.1:8080"); empty for none. Another
    // station forgets what this one had.
    void setStation(const QString& webAddress);
    const QString& station() const { return station_; }
    // The icons folder of an open layout (looked at before the station); empty for none.
    void setFolder(const QString& iconsFolder);
    const QString& folder() const { return folder_; }

    // The picture of a locomotive whose `.icon` is `icon`, when it is known; otherwise nullopt, and the
    // search starts (once): picturesChanged() says when it ended.
    std::optional<QByteArray> picture(const QString& icon);
    Status status(const QString& icon) const;
    // Why the picture is missing or failed, in English ("the station has no picture BR 86.png").
    QString problem(const QString& icon) const;
    Reason reason(const QString& icon) const;
    // Where the picture came from ("http://.../icons/BR%2086.png", a file path), when present.
    QString source(const QString& icon) const;
    // Where the picture was looked for last, found or not: the address asked ("http://127.0.0.1:8080/
    // icons/BR%2086.png") or the file read; empty while nothing was asked.
    QString lookedAt(const QString& icon) const;

    // The station is back: pictures whose fetch failed are asked for again when next wanted.
    void retryFailed();

signals:
    void picturesChanged();

private:
    struct Entry {
        Status status = Status::Unknown;
        Reason reason = Reason::None;
        QByteArray bytes;
        QString problem;
        QString source;
        QDateTime failedAt;
    };

    const Entry* entryFor(const QString& icon) const;
    void look(const QString& fileName, Entry& entry);
    bool readFromFolder(const QString& fileName, Entry& entry) const;
    void startFetches();
    void fetch(const QString& fileName);
    void fetched(QNetworkReply* reply, const QString& fileName);
    void settle(const QString& fileName, Status status, Reason reason, QByteArray bytes, QString problem);
    void forgetAll();

    Settings settings_;
    QNetworkAccessManager* network_;
    QString station_;
    QString folder_;
    std::map<QString, Entry> entries_; // by file name ("BR 218.png")
    std::deque<QString> waiting_;
    std::map<QNetworkReply*, QString> running_;
};

} // namespace stellwerk::connection
