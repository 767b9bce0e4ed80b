#include "cs2config/LocomotiveStateFile.h"

#include "cs2config/JsonWriter.h"
#include "cs2config/LocomotiveFieldWriter.h"
#include "cs2config/LocomotiveJson.h"
#include "cs2config/LocomotiveKeys.h"
#include "cs2config/LocomotiveSections.h"
#include "cs2config/LocomotiveValues.h"

#include <algorithm>
#include <array>
#include <unordered_map>

namespace stellwerk::cs2config {

namespace {

namespace key = locokey;
using loco::FieldWriter;
using loco::Findings;
using loco::RecordLines;
using Base = FieldWriter::Base;
using Presence = FieldWriter::Presence;

enum StateValue : std::size_t { Name, Velocity, Richtung };
constexpr std::array<std::string_view, 3> stateKeys{key::name, key::velocity, key::richtung};
constexpr std::array<std::string_view, 1> stateBlocks{key::funktionen};
enum FunctionValue : std::size_t { Nr, Wert };
constexpr std::array<std::string_view, 2> functionKeys{key::nr, key::wert};

// Reads the status records one by one and checks that each can be matched to a locomotive.
class StateReader {
public:
    StateReader(Diagnostics& diagnostics, Findings& findings)
        : diagnostics_(diagnostics), findings_(findings) {}

    LocomotiveState read(const Node& record) {
        const RecordLines lines(record, {stateKeys, stateBlocks, "locomotive status record"}, diagnostics_,
                                findings_);
        loco::ValueReader values(diagnostics_, loco::TextCoding::Plain);
        LocomotiveState state;
        state.name = values.text(lines[Name]);
        state.velocity = values.number(lines[Velocity], 0);
        state.direction = direction(lines[Richtung]);
        state.source = record;
        for (const Node& block : record.children())
            if (block.isEntry() && block.key() == key::funktionen)
                state.functions.push_back(function(block, values));
        if (state.name.empty())
            findings_.note(Findings::Kind::MissingKey, ".name", "locomotive status record without a name",
                           "kept; it cannot be matched to a locomotive", record.lineNumber());
        checkFunctions(state);
        return state;
    }

private:
    TravelDirection direction(const Node* line) {
        const loco::ReadValue<TravelDirection> read = loco::readDirection(line);
        if (read.problem == loco::ValueProblem::NotANumber || read.problem == loco::ValueProblem::OutOfRange)
            findings_.note(Findings::Kind::Other, {},
                           "direction '.richtung=" + std::string(trimmed(line->value()).substr(0, 20)) +
                               "' is neither 0 (forward) nor 1 (backward)",
                           "read as unknown; kept unchanged", line->lineNumber());
        return read.value;
    }

    FunctionState function(const Node& block, loco::ValueReader& values) {
        const RecordLines lines(block, {functionKeys, {}, "function block"}, diagnostics_, findings_);
        FunctionState state{values.number(lines[Nr], -1), values.number(lines[Wert], 0), block};
        if (!lines[Nr])
            findings_.note(Findings::Kind::Other, {}, "function block without '..nr'",
                           "kept unchanged; not numbered", block.lineNumber());
        return state;
    }

    void checkFunctions(const LocomotiveState& state) {
        std::unordered_map<int, int> firstLine;
        for (const FunctionState& function : state.functions) {
            if (function.number < 0)
                continue;
            const int line = function.source.lineNumber();
            const auto [first, added] = firstLine.try_emplace(function.number, line);
            if (!added)
                diagnostics_.warning(line,
                                     "F" + std::to_string(function.number) +
                                         " appears twice in the status of " +
                                         loco::nameOf(state.name, state.source.lineNumber()) + " (lines " +
                                         std::to_string(first->second) + " and " + std::to_string(line) + ")",
                                     "both kept");
        }
    }

    Diagnostics& diagnostics_;
    Findings& findings_;
};

void checkDuplicateNames(const std::vector<LocomotiveState>& states, Diagnostics& diagnostics) {
    std::unordered_map<std::string_view, const LocomotiveState*> seen;
    for (const LocomotiveState& state : states) {
        if (state.name.empty())
            continue;
        const auto [first, added] = seen.try_emplace(state.name, &state);
        if (!added)
            diagnostics.warning(state.source.lineNumber(),
                                "two status records for " +
                                    loco::nameOf(state.name, state.source.lineNumber()) + " (lines " +
                                    std::to_string(first->second->source.lineNumber()) + " and " +
                                    std::to_string(state.source.lineNumber()) + ")",
                                "both kept; the first one belongs to the locomotive");
    }
}

Node writeState(const LocomotiveState& state, const LineStyle& style) {
    const bool fresh = !state.source.isEntry();
    Node record = fresh ? Node::entry(0, key::locomotive, std::nullopt, style) : state.source;
    FieldWriter fields(record, style, fresh);
    fields.text(key::name, state.name, Presence::Required);
    fields.number(key::velocity, state.velocity, 0, Base::Decimal);
    fields.direction(key::richtung, state.direction);
    std::vector<Node> blocks;
    for (const FunctionState& function : state.functions) {
        Node block = function.source.isEntry() ? function.source
                                               : Node::entry(1, key::funktionen, std::nullopt, style);
        FieldWriter functionFields(block, style, !function.source.isEntry());
        functionFields.number(key::nr, function.number, -1, Base::Decimal, Presence::Required);
        functionFields.number(key::wert, function.value, 0, Base::Decimal);
        blocks.push_back(std::move(block));
    }
    loco::replaceBlocks(record, {key::funktionen}, std::move(blocks));
    loco::keepFinalEnding(record, style);
    return record;
}

} // namespace

const FunctionState* LocomotiveState::function(int number) const {
    const auto found = std::find_if(functions.begin(), functions.end(),
                                    [number](const FunctionState& f) { return f.number == number; });
    return found == functions.end() ? nullptr : &*found;
}

LocomotiveStateFile LocomotiveStateFile::read(const Document& document, Diagnostics& diagnostics) {
    LocomotiveStateFile file;
    file.document = document;
    Findings findings;
    loco::checkSection(document, {key::section, key::stateSection}, diagnostics);
    if (const auto version = loco::readVersion(document, diagnostics, findings))
        file.version = Version{version->major, version->minor};
    loco::noteUnknownRecords(document, {key::locomotive, key::version}, findings);
    StateReader reader(diagnostics, findings);
    for (const Node* record : document.records(key::locomotive))
        file.locomotives.push_back(reader.read(*record));
    checkDuplicateNames(file.locomotives, diagnostics);
    findings.report(diagnostics);
    return file;
}

Document LocomotiveStateFile::write() const {
    Document out = document;
    loco::writeVersion(out, version ? std::optional<loco::RecordVersion>({version->major, version->minor})
                                    : std::nullopt);
    std::vector<Node> records;
    records.reserve(locomotives.size());
    for (const LocomotiveState& state : locomotives)
        records.push_back(writeState(state, out.style()));
    out.replaceRecords(key::locomotive, std::move(records));
    return out;
}

const LocomotiveState* LocomotiveStateFile::find(std::string_view name) const {
    const auto found = std::find_if(locomotives.begin(), locomotives.end(),
                                    [name](const LocomotiveState& state) { return state.name == name; });
    return found == locomotives.end() ? nullptr : &*found;
}

std::string toJson(const LocomotiveStateFile& file) {
    JsonWriter json;
    json.beginObject().value("kind", "lokomotive.sr2");
    loco::writeVersionJson(json, file.version);
    json.beginArray("locomotives");
    for (const LocomotiveState& state : file.locomotives) {
        json.beginObject()
            .value("line", state.source.lineNumber())
            .value("name", state.name)
            .value("velocity", state.velocity)
            .value("direction", directionName(state.direction));
        json.beginArray("functions");
        for (const FunctionState& function : state.functions)
            json.beginObject().value("number", function.number).value("value", function.value).endObject();
        json.endArray().endObject();
    }
    json.endArray().endObject();
    return json.text();
}

} // namespace stellwerk::cs2config
