#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/Node.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// One step of a route (an ".item" block): switch an accessory to a position, or run another route,
// optionally after a wait.
struct RouteStep {
    static constexpr std::string_view accessoryType = "mag";

    std::string type = std::string(accessoryType); // ..typ: "mag" for an accessory; empty when missing
    std::int64_t accessory = 0;                    // ..magnetartikel: keyboard id; 0 when running a route
    std::int64_t position = 0;                     // ..stellung, 0 when the line is missing
    std::int64_t routeReference = -1;              // ..fsverweis: route to run; -1 (or missing) for none
    std::optional<std::int64_t> delayMs;           // ..sekunde: wait before the step ("2.3" = 2300 ms)
    Node source;                                   // the block as read (empty for a new step)

    bool runsRoute() const { return routeReference >= 0; }
    int lineNumber() const { return source.lineNumber(); }
};

// A feedback contact that must be occupied (or free) for the route to run (an ".S88Flag" block).
struct RouteCondition {
    std::int64_t contact = 0; // ..kont
    bool occupied = true;     // ..hi: 0 = the contact must be free; missing or 1 = occupied
    Node source;

    int lineNumber() const { return source.lineNumber(); }
};

// One route of fahrstrassen.cs2: what it switches, in order, and what starts it.
struct Route {
    std::int64_t id = 0;                        // .id
    std::string name;                           // .name
    std::int64_t triggerContact = 0;            // .s88: contact whose closing starts the route; 0 = none
    std::optional<std::int64_t> releaseContact; // .s88Ein: contact whose opening starts it (kept when 0)
    std::int64_t mode = 0;                      // .extern: 0 manual, 1 mixed automatic
    std::vector<RouteCondition> conditions;     // .S88Flag blocks
    std::vector<RouteStep> steps;               // .item blocks, in switching order
    Node source;

    int lineNumber() const { return source.lineNumber(); }
};

// fahrstrassen.cs2: the station's routes and the file they came from.
struct RouteFile {
    static constexpr std::string_view section = "fahrstrassen";
    static constexpr std::string_view recordKeyword = "fahrstrasse";

    Document document = Document::create(section);
    std::optional<std::int64_t> versionMajor;
    std::optional<std::int64_t> versionMinor;
    std::vector<Route> routes;

    // Reads every "fahrstrasse" record; reports unknown keys and step types once, values that are not
    // numbers, missing ids, duplicate route ids, steps that switch nothing and references to missing routes.
    static RouteFile read(const Document& document, Diagnostics& diagnostics);
    // The source document with each route's record updated; unchanged routes keep their bytes.
    Document write() const;

    const Route* find(std::int64_t id) const;
};

std::string toJson(const RouteFile& file);

} // namespace stellwerk::cs2config
