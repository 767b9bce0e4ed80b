#include "sim/AccidentWatch.h"

#include "sim/TurnoutWatch.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace stellwerk::sim {

using trackgraph::LeadKind;
using trackgraph::TileRole;

namespace {

bool overlap(const RunExtent& first, const RunExtent& second) {
    if (first.block != 0 || second.block != 0)
        return first.block == second.block && first.fromMm < second.toMm && second.fromMm < first.toMm;
    if (first.tile != second.tile)
        return false;
    return first.junction ||
           (first.leg == second.leg && first.fromMm < second.toMm && second.fromMm < first.toMm);
}

} // namespace

std::string_view accidentKindName(AccidentKind kind) {
    switch (kind) {
    case AccidentKind::Collision:
        return "collision";
    case AccidentKind::BufferStop:
        return "buffer stop";
    case AccidentKind::TurnoutRunThrough:
        break;
    }
    return "turnout run through";
}

Accident AccidentWatch::counted(AccidentKind kind, std::vector<std::uint32_t> trains, std::string text) {
    switch (kind) {
    case AccidentKind::Collision:
        ++counts_.collisions;
        break;
    case AccidentKind::BufferStop:
        ++counts_.bufferStops;
        break;
    case AccidentKind::TurnoutRunThrough:
        ++counts_.turnoutsRunThrough;
        break;
    }
    log_.push_back({kind, std::move(trains), std::string(accidentKindName(kind)) + ": " + std::move(text)});
    return log_.back();
}

std::optional<Accident> AccidentWatch::ranInto(const TrainOnTrack& train, const RunStop& stop) {
    const bool turnoutThere = graph_.tile(stop.tile).role() == TileRole::Turnout;
    const std::string where = beyondBlock(stop.lastBlock) + " (" + placeOf(stop.tile) + ")";
    switch (stop.kind) {
    case LeadKind::BufferStop:
        return counted(AccidentKind::BufferStop, {train.locId},
                       train.name + " ran into the buffer stop" + where);
    case LeadKind::Turntable:
        return counted(AccidentKind::BufferStop, {train.locId},
                       train.name + " ran off the track at the turntable" + where);
    case LeadKind::OpenEnd:
        if (turnoutThere)
            break;
        return counted(AccidentKind::BufferStop, {train.locId},
                       train.name + " ran off the open end of the track" + where);
    case LeadKind::SetAgainst:
    case LeadKind::NotSet:
        break;
    case LeadKind::Block:
    case LeadKind::TooLong:
        return std::nullopt;
    }
    return counted(AccidentKind::TurnoutRunThrough, {train.locId}, turnoutStop(train, stop));
}

std::string AccidentWatch::turnoutStop(const TrainOnTrack& train, const RunStop& stop) const {
    const std::string turnout = turnoutName(stop.article);
    const std::string where = " (" + placeOf(stop.turnout.value_or(stop.tile)) + ")";
    switch (stop.kind) {
    case LeadKind::SetAgainst:
        return train.name +
               (stop.facing ? " ran into " + turnout + " set for other tracks"
                            : " ran through " + turnout + " set against it") +
               where;
    case LeadKind::NotSet:
        return train.name + " ran into " + turnout + (stop.article ? " while it was moving" : "") + where;
    default:
        break;
    }
    const trackgraph::Tile& tile = graph_.tile(stop.tile);
    return train.name + " left " + turnoutName(tile.accessory) + " where its way leads nowhere" + where;
}

std::vector<Accident> AccidentWatch::collisions(const std::vector<TrainOnTrack>& trains) {
    std::vector<Accident> accidents;
    for (std::size_t i = 0; i < trains.size(); ++i)
        for (std::size_t j = i + 1; j < trains.size(); ++j) {
            if (trains[i].derailed && trains[j].derailed)
                continue;
            if (const std::optional<std::string> where = touching(trains[i], trains[j]))
                accidents.push_back(counted(AccidentKind::Collision, {trains[i].locId, trains[j].locId},
                                            trains[i].name + " and " + trains[j].name + " " + *where));
        }
    return accidents;
}

std::optional<std::string> AccidentWatch::touching(const TrainOnTrack& first,
                                                   const TrainOnTrack& second) const {
    const std::vector<RunExtent> theirs = second.run->extents(graph_);
    for (const RunExtent& mine : first.run->extents(graph_))
        for (const RunExtent& other : theirs)
            if (overlap(mine, other))
                return whereTouching(mine);
    return std::nullopt;
}

std::string AccidentWatch::whereTouching(const RunExtent& extent) const {
    if (extent.block != 0)
        return "in block \"" + graph_.block(extent.block).name + "\"";
    const trackgraph::Tile& tile = graph_.tile(extent.tile);
    const std::string where = " (" + placeOf(extent.tile) + ")";
    if (tile.role() == TileRole::Turnout)
        return "on " + turnoutName(tile.accessory) + where;
    if (tile.role() == TileRole::Crossing)
        return "on the crossing" + where;
    return "between blocks" + where;
}

std::optional<Accident> AccidentWatch::switchedUnder(const TrainOnTrack& train,
                                                     const TurnoutWatch& turnouts) {
    if (train.derailed)
        return std::nullopt;
    for (const TurnoutUnder& under : train.run->turnoutsUnder(graph_)) {
        const trackgraph::Tile& tile = graph_.tile(under.tile);
        if (!tile.accessory)
            continue;
        const std::optional<int> position = turnouts.settled(*tile.accessory);
        if (position && tile.shape.legs()[under.leg].setIn(*position))
            continue;
        return counted(AccidentKind::TurnoutRunThrough, {train.locId},
                       turnoutName(tile.accessory) + " moved under " + train.name + " (" +
                           placeOf(under.tile) + ")");
    }
    return std::nullopt;
}

std::string AccidentWatch::turnoutName(std::optional<std::int64_t> article) const {
    return article ? "turnout " + std::to_string(*article)
                   : std::string("a turnout without a keyboard number");
}

std::string AccidentWatch::placeOf(trackgraph::TileId tile) const {
    const trackgraph::Tile& where = graph_.tile(tile);
    return "page '" + graph_.pages()[where.page].name + "', column " + std::to_string(where.place.column) +
           ", row " + std::to_string(where.place.row);
}

std::string AccidentWatch::beyondBlock(int block) const {
    return block == 0 ? std::string() : " beyond block \"" + graph_.block(block).name + "\"";
}

std::string accidentsJson(const AccidentCounts& counts, const std::vector<Accident>& log) {
    QJsonArray lines;
    for (const Accident& accident : log)
        lines.append(QString::fromStdString(accident.text));
    const QJsonObject object{{"collisions", counts.collisions},
                             {"bufferStops", counts.bufferStops},
                             {"turnoutsRunThrough", counts.turnoutsRunThrough},
                             {"total", counts.total()},
                             {"accidents", lines}};
    return QJsonDocument(object).toJson(QJsonDocument::Compact).toStdString();
}

} // namespace stellwerk::sim
