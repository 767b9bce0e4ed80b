#include "operation/TrainBook.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <algorithm>
#include <cmath>

namespace stellwerk::operation {

namespace {

constexpr int Version = 1;

QJsonObject scheduleJson(const automation::Schedule& schedule) {
    QJsonArray stops;
    for (const automation::ScheduleStop& stop : schedule.stops)
        stops.append(QJsonObject{{QStringLiteral("block"), QString::fromStdString(stop.block)},
                                 {QStringLiteral("dwell"), double(stop.dwellMs) / 1000.0}});
    return {{QStringLiteral("loop"), schedule.loop},
            {QStringLiteral("next"), qint64(schedule.next)},
            {QStringLiteral("stops"), stops}};
}

QJsonObject trainJson(const BookedTrain& train) {
    return {{QStringLiteral("loc"), qint64(train.locId)},
            {QStringLiteral("length"), train.lengthMm},
            {QStringLiteral("pushPull"), train.pushPull},
            {QStringLiteral("block"), QString::fromStdString(train.block)},
            {QStringLiteral("blockId"), train.blockId},
            {QStringLiteral("towards"),
             train.towards == trackgraph::End::A ? QStringLiteral("a") : QStringLiteral("b")},
            {QStringLiteral("automatic"), train.automatic},
            {QStringLiteral("schedule"), scheduleJson(train.schedule)}};
}

Expected<automation::Schedule, std::string> scheduleOf(const QJsonObject& object) {
    automation::Schedule schedule;
    schedule.loop = object.value(QStringLiteral("loop")).toBool();
    for (const QJsonValue& value : object.value(QStringLiteral("stops")).toArray()) {
        const QJsonObject stop = value.toObject();
        const QString block = stop.value(QStringLiteral("block")).toString();
        const double dwell = stop.value(QStringLiteral("dwell")).toDouble(-1);
        if (block.isEmpty() || dwell < 0)
            return std::string("a schedule's stop needs a block and a dwell of 0 seconds or more");
        schedule.stops.push_back({block.toStdString(), std::int64_t(std::lround(dwell * 1000)), 0});
    }
    const qint64 next = object.value(QStringLiteral("next")).toInteger(0);
    schedule.next = next < 0 || std::size_t(next) > schedule.stops.size() ? 0 : std::size_t(next);
    return schedule;
}

Expected<BookedTrain, std::string> trainOf(const QJsonObject& object) {
    BookedTrain train;
    const qint64 loc = object.value(QStringLiteral("loc")).toInteger(-1);
    if (loc <= 0 || loc > 0xFFFFFFFF)
        return std::string("a train without a locomotive (\"loc\")");
    train.locId = std::uint32_t(loc);
    train.lengthMm = object.value(QStringLiteral("length")).toInt(200);
    if (train.lengthMm <= 0)
        return std::string("a train of length " + std::to_string(train.lengthMm) + " mm");
    train.pushPull = object.value(QStringLiteral("pushPull")).toBool();
    train.block = object.value(QStringLiteral("block")).toString().toStdString();
    train.blockId = object.value(QStringLiteral("blockId")).toInt();
    const QString towards = object.value(QStringLiteral("towards")).toString(QStringLiteral("b"));
    if (towards != QLatin1String("a") && towards != QLatin1String("b"))
        return std::string("a train facing end \"" + towards.toStdString() + "\" (a or b)");
    train.towards = towards == QLatin1String("a") ? trackgraph::End::A : trackgraph::End::B;
    train.automatic = object.value(QStringLiteral("automatic")).toBool();
    auto schedule = scheduleOf(object.value(QStringLiteral("schedule")).toObject());
    if (!schedule)
        return schedule.error();
    train.schedule = std::move(*schedule);
    train.schedule.pushPull = train.pushPull;
    return train;
}

} // namespace

const BookedTrain* TrainBook::find(std::uint32_t locId) const {
    const auto found = std::find_if(trains_.begin(), trains_.end(),
                                    [locId](const BookedTrain& train) { return train.locId == locId; });
    return found == trains_.end() ? nullptr : &*found;
}

BookedTrain* TrainBook::find(std::uint32_t locId) {
    return const_cast<BookedTrain*>(std::as_const(*this).find(locId));
}

void TrainBook::put(BookedTrain train) {
    if (BookedTrain* known = find(train.locId))
        *known = std::move(train);
    else
        trains_.push_back(std::move(train));
}

void TrainBook::remove(std::uint32_t locId) {
    std::erase_if(trains_, [locId](const BookedTrain& train) { return train.locId == locId; });
}

std::string TrainBook::toJson() const {
    QJsonArray trains;
    for (const BookedTrain& train : trains_)
        trains.append(trainJson(train));
    const QJsonObject root{{QStringLiteral("version"), Version}, {QStringLiteral("trains"), trains}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
}

Expected<TrainBook, std::string> TrainBook::fromJson(std::string_view json) {
    QJsonParseError error;
    const QJsonDocument document =
        QJsonDocument::fromJson(QByteArray(json.data(), qsizetype(json.size())), &error);
    if (document.isNull())
        return "not JSON: " + error.errorString().toStdString() + " at byte " + std::to_string(error.offset);
    const QJsonObject root = document.object();
    if (!root.value(QStringLiteral("trains")).isArray())
        return std::string("no list of trains (\"trains\")");
    if (root.value(QStringLiteral("version")).toInt(Version) > Version)
        return std::string("written by a newer Stellwerk (version ") +
               std::to_string(root.value(QStringLiteral("version")).toInt()) + ")";
    TrainBook book;
    for (const QJsonValue& value : root.value(QStringLiteral("trains")).toArray()) {
        auto train = trainOf(value.toObject());
        if (!train)
            return train.error();
        book.put(std::move(*train));
    }
    return book;
}

} // namespace stellwerk::operation
