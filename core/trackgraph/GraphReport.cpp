#include "trackgraph/GraphReport.h"

#include <sstream>

namespace stellwerk::trackgraph {

namespace {

using cs2config::JsonWriter;

void writePlace(JsonWriter& json, const TrackGraph& graph, TileId tile) {
    const TilePlace& place = graph.tile(tile).place;
    json.value("page", place.page).value("x", place.column).value("y", place.row);
}

void writeTile(JsonWriter& json, const TrackGraph& graph, TileId tile) {
    json.beginObject();
    writePlace(json, graph, tile);
    json.endObject();
}

void writeArticle(JsonWriter& json, const std::optional<std::int64_t>& article) {
    if (article)
        json.value("article", *article);
    else
        json.null("article");
}

void writeEnd(JsonWriter& json, const TrackGraph& graph, const BlockEndInfo& end, std::string_view key) {
    json.beginObject(key);
    writePlace(json, graph, end.tile);
    json.value("side", portName(end.port)).value("beyond", endKindName(end.beyond));
    json.endObject();
}

void writeContacts(JsonWriter& json, const TrackGraph& graph, const Block& block) {
    json.beginArray("contacts");
    for (const ContactOnBlock& contact : block.contacts)
        json.value({}, contact.contact.number);
    json.endArray();
    json.beginArray("contactPlaces");
    for (const ContactOnBlock& contact : block.contacts) {
        json.beginObject().value("contact", contact.contact.number).value("device", contact.contact.device);
        writePlace(json, graph, contact.tile);
        json.value("from", contact.fromMm).value("to", contact.toMm).endObject();
    }
    json.endArray();
}

void writeSignals(JsonWriter& json, const TrackGraph& graph, const std::vector<SignalOnTrack>& along,
                  bool onBlock) {
    json.beginArray("signals");
    for (const SignalOnTrack& signal : along) {
        json.beginObject();
        writeArticle(json, signal.article);
        json.value("name", signal.name);
        writePlace(json, graph, signal.tile);
        if (onBlock)
            json.value("towards", endName(signal.towards));
        else
            json.value("facesTravel", signal.facesTravel);
        json.value("at", signal.atMm).endObject();
    }
    json.endArray();
}

void writeBlock(JsonWriter& json, const TrackGraph& graph, const Block& block) {
    json.beginObject().value("id", block.id).value("name", block.name);
    writeContacts(json, graph, block);
    json.beginArray("tiles");
    for (const TileId tile : block.tiles)
        writeTile(json, graph, tile);
    json.endArray();
    json.beginObject("ends");
    writeEnd(json, graph, block.end(End::A), "a");
    writeEnd(json, graph, block.end(End::B), "b");
    json.endObject();
    writeSignals(json, graph, block.signalsAlong, true);
    json.value("length", block.lengthTiles()).value("lengthMm", block.lengthMm).endObject();
}

void writeBlockEnd(JsonWriter& json, const BlockEnd& end, std::string_view key) {
    json.beginObject(key).value("block", end.block).value("end", endName(end.end)).endObject();
}

void writeTurnouts(JsonWriter& json, const TrackGraph& graph, const Connection& connection) {
    json.beginArray("turnouts");
    for (const TurnoutOnWay& turnout : connection.turnouts) {
        json.beginObject();
        writeArticle(json, turnout.article);
        json.value("position", positionName(turnout.kind, turnout.position))
            .value("setting", turnout.position)
            .value("facing", turnout.facing);
        writePlace(json, graph, turnout.tile);
        json.endObject();
    }
    json.endArray();
}

void writeNumbers(JsonWriter& json, std::string_view key, const auto& numbers) {
    json.beginArray(key);
    for (const auto number : numbers)
        json.value({}, std::int64_t(number));
    json.endArray();
}

void writeConnection(JsonWriter& json, const TrackGraph& graph, const Connection& connection) {
    json.beginObject().value("id", connection.id);
    writeBlockEnd(json, connection.from, "from");
    writeBlockEnd(json, connection.to, "to");
    writeTurnouts(json, graph, connection);
    json.beginArray("crossings");
    for (const TileId tile : connection.crossings)
        writeTile(json, graph, tile);
    json.endArray();
    writeSignals(json, graph, connection.signalsAlong, false);
    writeNumbers(json, "routes", connection.routes);
    writeNumbers(json, "conflicts", connection.conflicts);
    json.value("length", int(connection.path.size())).value("lengthMm", connection.lengthMm).endObject();
}

void writeProblem(JsonWriter& json, const TrackGraph& graph, const Problem& problem) {
    json.beginObject();
    writePlace(json, graph, problem.tile);
    json.value("kind", problemKindName(problem.kind)).value("text", problem.text).endObject();
}

} // namespace

void writeJson(JsonWriter& json, const TrackGraph& graph) {
    json.beginObject();
    json.beginArray("pages");
    for (const GraphPage& page : graph.pages())
        json.beginObject()
            .value("id", page.id)
            .value("name", page.name)
            .value("loaded", page.loaded)
            .endObject();
    json.endArray();
    json.beginArray("blocks");
    for (const Block& block : graph.blocks())
        writeBlock(json, graph, block);
    json.endArray();
    json.beginArray("connections");
    for (const Connection& connection : graph.connections())
        writeConnection(json, graph, connection);
    json.endArray();
    json.beginArray("problems");
    for (const Problem& problem : graph.problems())
        writeProblem(json, graph, problem);
    json.endArray();
    json.endObject();
}

std::string toJson(const TrackGraph& graph) {
    JsonWriter json;
    writeJson(json, graph);
    return json.text() + "\n";
}

} // namespace stellwerk::trackgraph
