#include "cs2config/RouteFile.h"

#include "cs2config/AccessoryRecordSupport.h"
#include "cs2config/JsonWriter.h"
#include "cs2config/RecordFile.h"
#include "cs2config/RouteDelay.h"
#include "cs2config/Text.h"

namespace stellwerk::cs2config {

namespace {

using accessories::OnceReporter;
using accessories::RecordReader;
using accessories::RecordWriter;
using accessories::writeOptional;

constexpr std::string_view stepKey = "item";
constexpr std::string_view conditionKey = "S88Flag";

std::optional<std::int64_t> delayIn(const Node& step) {
    const std::optional<std::string_view> text = step.valueOf("sekunde");
    return text ? parseRouteDelay(*text) : std::nullopt;
}

std::optional<std::int64_t> readDelay(const Node& step, Diagnostics& diagnostics) {
    const Node* line = step.find("sekunde");
    if (!line)
        return std::nullopt;
    const std::optional<std::int64_t> delay = delayIn(step);
    if (!delay)
        diagnostics.warning(line->lineNumber(),
                            "value " + quoteForMessage(line->value()) +
                                " of ..sekunde is not a wait in seconds",
                            "kept unchanged; no wait used");
    return delay;
}

void checkStep(const RouteStep& step, OnceReporter& reporter) {
    const bool accessoryStep = step.type.empty() || step.type == RouteStep::accessoryType;
    if (!accessoryStep) {
        reporter.once("step type " + step.type, step.lineNumber(),
                      "unknown route step type ..typ=" + quoteForMessage(step.type),
                      "kept; reported once for the whole file");
        return;
    }
    if (!step.runsRoute() && step.accessory <= 0)
        reporter.diagnostics().warning(step.lineNumber(),
                                       "route step switches neither an accessory nor a route", "kept");
}

RouteStep readStep(const Node& block, OnceReporter& reporter) {
    reporter.checkKeys(block, "route steps (.item)",
                       {"typ", "magnetartikel", "stellung", "fsverweis", "sekunde"});
    RecordReader reader(block, "route step", reporter.diagnostics());
    RouteStep step;
    step.source = block;
    step.type = reader.keyword("typ");
    step.accessory = reader.integer("magnetartikel", 0);
    step.position = reader.integer("stellung", 0);
    step.routeReference = reader.integer("fsverweis", -1);
    step.delayMs = readDelay(block, reporter.diagnostics());
    checkStep(step, reporter);
    return step;
}

RouteCondition readCondition(const Node& block, OnceReporter& reporter) {
    reporter.checkKeys(block, "route conditions (.S88Flag)", {"kont", "hi"});
    RecordReader reader(block, "route condition", reporter.diagnostics());
    RouteCondition condition;
    condition.source = block;
    condition.contact = reader.required("kont");
    condition.occupied = reader.integer("hi", 1) != 0;
    return condition;
}

Route readRoute(const Node& record, OnceReporter& reporter) {
    reporter.checkKeys(record, "fahrstrasse records",
                       {"id", "name", "s88", "s88Ein", "extern", stepKey, conditionKey},
                       {stepKey, conditionKey});
    RecordReader reader(record, "fahrstrasse record", reporter.diagnostics());
    Route route;
    route.source = record;
    route.id = reader.required("id");
    route.name = reader.text("name");
    route.triggerContact = reader.integer("s88", 0);
    route.releaseContact = reader.optionalInteger("s88Ein");
    route.mode = reader.integer("extern", 0);
    for (const Node& child : record.children()) {
        if (!child.isEntry())
            continue;
        if (child.key() == stepKey)
            route.steps.push_back(readStep(child, reporter));
        else if (child.key() == conditionKey)
            route.conditions.push_back(readCondition(child, reporter));
    }
    return route;
}

void checkRoutes(const std::vector<Route>& routes, Diagnostics& diagnostics) {
    const auto firstLine = accessories::firstLineOfEachId(routes, [&](const Route& route, int first) {
        diagnostics.warning(route.lineNumber(),
                            "duplicate route id " + std::to_string(route.id) + " (first at line " +
                                std::to_string(first) + ")",
                            "both kept");
    });
    for (const Route& route : routes)
        for (const RouteStep& step : route.steps)
            if (step.runsRoute() && !firstLine.contains(step.routeReference))
                diagnostics.warning(step.lineNumber(),
                                    "route " + std::to_string(route.id) + " runs route " +
                                        std::to_string(step.routeReference) +
                                        ", which the file does not have",
                                    "kept");
}

void writeDelay(RecordWriter& writer, const Node& source, const std::optional<std::int64_t>& delayMs) {
    if (delayIn(source) == delayMs)
        return;
    if (delayMs)
        writer.editor().setText("sekunde", formatRouteDelay(*delayMs));
    else
        writer.editor().remove("sekunde");
}

Node writeStep(const RouteStep& step, const LineStyle& style) {
    Node block = accessories::blockFrom(step.source, stepKey, style);
    RecordWriter writer(block, step.source, style);
    writer.optionalKeyword("typ", step.type);
    writer.integer("fsverweis", step.routeReference, -1);
    writeDelay(writer, step.source, step.delayMs);
    writer.integer("magnetartikel", step.accessory, 0);
    writer.integer("stellung", step.position, 0);
    return block;
}

Node writeCondition(const RouteCondition& condition, const LineStyle& style) {
    Node block = accessories::blockFrom(condition.source, conditionKey, style);
    RecordWriter writer(block, condition.source, style);
    writer.required("kont", condition.contact);
    writer.flag("hi", condition.occupied, true);
    return block;
}

Node writeRoute(const Route& route, const Document& document) {
    const LineStyle& style = document.style();
    Node record = accessories::recordFrom(route.source, document, RouteFile::recordKeyword);
    const Node::Ending ending = record.lastLine().ending();
    RecordWriter writer(record, route.source, style);
    writer.required("id", route.id);
    writer.optionalText("name", route.name);
    writer.integer("s88", route.triggerContact, 0);
    writer.optionalInteger("s88Ein", route.releaseContact);
    writer.integer("extern", route.mode, 0);
    std::vector<Node> conditions;
    for (const RouteCondition& condition : route.conditions)
        conditions.push_back(writeCondition(condition, style));
    std::vector<Node> steps;
    for (const RouteStep& step : route.steps)
        steps.push_back(writeStep(step, style));
    accessories::placeBlocks(record, conditionKey, std::move(conditions), stepKey);
    accessories::placeBlocks(record, stepKey, std::move(steps));
    accessories::endLines(record, ending, style);
    return record;
}

void writeStepJson(JsonWriter& json, const RouteStep& step) {
    json.beginObject();
    json.value("line", step.lineNumber());
    json.value("type", step.type);
    if (step.runsRoute())
        json.value("route", step.routeReference);
    else
        json.null("route");
    json.value("accessory", step.accessory);
    json.value("position", step.position);
    writeOptional(json, "delayMs", step.delayMs);
    json.endObject();
}

void writeRouteJson(JsonWriter& json, const Route& route) {
    json.beginObject();
    json.value("line", route.lineNumber());
    json.value("id", route.id);
    json.value("name", route.name);
    json.value("triggerContact", route.triggerContact);
    writeOptional(json, "releaseContact", route.releaseContact);
    json.value("mode", route.mode);
    json.beginArray("conditions");
    for (const RouteCondition& condition : route.conditions) {
        json.beginObject();
        json.value("line", condition.lineNumber());
        json.value("contact", condition.contact);
        json.value("occupied", condition.occupied);
        json.endObject();
    }
    json.endArray();
    json.beginArray("steps");
    for (const RouteStep& step : route.steps)
        writeStepJson(json, step);
    json.endArray();
    json.endObject();
}

constexpr accessories::RecordFileKind<RouteFile, Route> kind{.items = &RouteFile::routes,
                                                             .readAs = "routes",
                                                             .fileName = "fahrstrassen.cs2",
                                                             .jsonItems = "routes",
                                                             .read = readRoute,
                                                             .write = writeRoute,
                                                             .writeJson = writeRouteJson};

} // namespace

RouteFile RouteFile::read(const Document& document, Diagnostics& diagnostics) {
    RouteFile file = accessories::readRecordFile(kind, document, diagnostics);
    checkRoutes(file.routes, diagnostics);
    return file;
}

Document RouteFile::write() const {
    return accessories::writeRecordFile(kind, *this);
}

const Route* RouteFile::find(std::int64_t id) const {
    return accessories::findById(routes, id);
}

std::string toJson(const RouteFile& file) {
    return accessories::recordFileJson(kind, file);
}

} // namespace stellwerk::cs2config
