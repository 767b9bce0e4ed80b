#include "automation/Schedule.h"

#include "cs2/LocIdText.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>

namespace stellwerk::automation {

namespace {

Expected<Schedule, std::string> scheduleOf(const QJsonObject& train, const std::string& loc) {
    Schedule schedule;
    schedule.loop = train.value(QStringLiteral("loop")).toBool(false);
    schedule.pushPull = train.value(QStringLiteral("pushPull")).toBool(false);
    for (const QJsonValue& value : train.value(QStringLiteral("stops")).toArray()) {
        const QJsonObject stop = value.toObject();
        const QString block = stop.value(QStringLiteral("block")).toString();
        const double dwell = stop.value(QStringLiteral("dwell")).toDouble(0);
        if (block.isEmpty())
            return loc + ": a stop without \"block\"";
        if (!(dwell >= 0) || dwell > 24 * 3600)
            return loc + ": the dwell at \"" + block.toStdString() + "\" is not a number of seconds";
        schedule.stops.push_back({block.toStdString(), std::int64_t(std::llround(dwell * 1000)), 0});
    }
    if (schedule.stops.empty())
        return loc + ": a schedule needs at least one stop";
    const int next = train.value(QStringLiteral("next")).toInt(0);
    schedule.next = next >= 0 && std::size_t(next) <= schedule.stops.size() ? std::size_t(next) : 0;
    if (schedule.loop && schedule.next >= schedule.stops.size())
        schedule.next = 0;
    return schedule;
}

} // namespace

Expected<std::map<std::uint32_t, Schedule>, std::string> parseSchedules(std::string_view json) {
    QJsonParseError error{};
    const QJsonDocument document =
        QJsonDocument::fromJson(QByteArray(json.data(), qsizetype(json.size())), &error);
    if (error.error != QJsonParseError::NoError || !document.isObject())
        return "not a schedule file (JSON with \"trains\"): " + error.errorString().toStdString();
    std::map<std::uint32_t, Schedule> schedules;
    for (const QJsonValue& value : document.object().value(QStringLiteral("trains")).toArray()) {
        const QJsonObject train = value.toObject();
        const std::string loc = train.value(QStringLiteral("loc")).toString().toStdString();
        const auto locId = cs2::parseLocomotive(loc);
        if (!locId)
            return "\"" + loc + "\": " + locId.error();
        auto schedule = scheduleOf(train, loc);
        if (!schedule)
            return schedule.error();
        schedules[locId->value()] = std::move(*schedule);
    }
    if (schedules.empty())
        return std::string("the schedule file names no train (\"trains\": [...])");
    return schedules;
}

std::string schedulesJson(const std::map<std::uint32_t, Schedule>& schedules) {
    QJsonArray trains;
    for (const auto& [locId, schedule] : schedules) {
        QJsonArray stops;
        for (const ScheduleStop& stop : schedule.stops)
            stops.append(QJsonObject{{"block", QString::fromStdString(stop.block)},
                                     {"dwell", double(stop.dwellMs) / 1000.0}});
        trains.append(QJsonObject{{"loc", QStringLiteral("0x%1").arg(locId, 4, 16, QLatin1Char('0'))},
                                  {"loop", schedule.loop},
                                  {"next", qint64(schedule.next)},
                                  {"pushPull", schedule.pushPull},
                                  {"stops", stops}});
    }
    return QJsonDocument(QJsonObject{{"trains", trains}}).toJson(QJsonDocument::Indented).toStdString();
}

} // namespace stellwerk::automation
