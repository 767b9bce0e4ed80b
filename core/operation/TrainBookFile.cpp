#include "operation/TrainBookFile.h"

#include "model/LayoutInUse.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

namespace stellwerk::operation {

namespace {

QString pathText(const std::filesystem::path& path) {
    return QString::fromStdString(path.string());
}

// A file name of letters, digits and dashes.
std::string fileSafe(const std::string& text) {
    std::string safe;
    for (const char c : text)
        safe += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
    return safe;
}

// The name the unreadable file is put aside under: never one that exists.
QString asideName(const QString& file) {
    const QString stamp = QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss"));
    QString aside = file + QStringLiteral(".unreadable-") + stamp;
    for (int n = 2; QFileInfo::exists(aside); ++n)
        aside = file + QStringLiteral(".unreadable-") + stamp + QStringLiteral("-") + QString::number(n);
    return aside;
}

} // namespace

std::filesystem::path TrainBookFile::placeFor(const model::LayoutInUse& layout,
                                              const std::filesystem::path& dataDir,
                                              const std::string& station) {
    using Origin = model::LayoutInUse::Origin;
    const std::filesystem::path trains = dataDir / "trains";
    if (layout.origin() == Origin::Station)
        return trains /
               ("station-" + fileSafe(station.empty() ? std::string("simulated") : station) + ".json");
    if (layout.origin() != Origin::Folder)
        return {};
    const std::filesystem::path config = layout.folder();
    const std::filesystem::path beside = config.filename() == "config" ? config.parent_path() : config;
    if (QFileInfo(pathText(beside)).isWritable())
        return beside / "stellwerk-trains.json";
    const QByteArray hash =
        QCryptographicHash::hash(pathText(beside).toUtf8(), QCryptographicHash::Sha1).toHex().left(12);
    return trains / ("folder-" + fileSafe(beside.filename().string()) + "-" + hash.toStdString() + ".json");
}

TrainBook TrainBookFile::load(std::string& problem) {
    problem.clear();
    QFile file(pathText(path_));
    if (!file.exists())
        return {};
    if (!file.open(QIODevice::ReadOnly)) {
        problem =
            "The trains' book " + path_.string() + " cannot be read: " + file.errorString().toStdString();
        return {};
    }
    const QByteArray bytes = file.readAll();
    file.close();
    auto book = TrainBook::fromJson(std::string_view(bytes.constData(), std::size_t(bytes.size())));
    if (book)
        return *book;
    const QString aside = asideName(file.fileName());
    const bool moved = QFile::rename(file.fileName(), aside);
    damagedInPlace_ = !moved;
    problem = "The trains' book " + path_.string() + " is damaged (" + book.error() + "); " +
              (moved ? "it was kept as " + aside.toStdString() : std::string("it was left as it is")) +
              " and the trains start unplaced.";
    return {};
}

std::string TrainBookFile::save(const TrainBook& book) const {
    if (path_.empty())
        return "no layout is in use";
    if (damagedInPlace_)
        return "The trains' book " + path_.string() +
               " is damaged and could not be put aside: it is not overwritten";
    QDir().mkpath(pathText(path_.parent_path()));
    QSaveFile file(pathText(path_));
    const std::string json = book.toJson();
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(json.data(), qint64(json.size())) != qint64(json.size()) || !file.commit())
        return "The trains' book " + path_.string() +
               " cannot be written: " + file.errorString().toStdString();
    return {};
}

} // namespace stellwerk::operation
