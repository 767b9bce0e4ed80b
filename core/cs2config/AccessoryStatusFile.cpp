#include "cs2config/AccessoryStatusFile.h"

#include "cs2config/AccessoryRecordSupport.h"
#include "cs2config/JsonWriter.h"

#include <map>

namespace stellwerk::cs2config {

namespace {

using accessories::OnceReporter;
using accessories::RecordReader;
using accessories::RecordWriter;
using accessories::writeOptional;

AccessoryState readState(const Node& record, OnceReporter& reporter) {
    reporter.checkKeys(record, "artikel records", {"id", "stellung"});
    RecordReader reader(record, "artikel record", reporter.diagnostics());
    AccessoryState state;
    state.source = record;
    state.id = reader.required("id");
    state.position = reader.integer("stellung", 0);
    return state;
}

void checkDuplicates(const std::vector<AccessoryState>& states, Diagnostics& diagnostics) {
    std::map<std::int64_t, int> firstLine;
    for (const AccessoryState& state : states) {
        const auto [it, inserted] = firstLine.emplace(state.id, state.lineNumber());
        if (!inserted)
            diagnostics.warning(state.lineNumber(),
                                "state of accessory " + std::to_string(state.id) +
                                    " given again (first at line " + std::to_string(it->second) + ")",
                                "both kept; the first one is used");
    }
}

Node writeState(const AccessoryState& state, const Document& document) {
    Node record = accessories::recordFrom(state.source, document, AccessoryStatusFile::recordKeyword);
    RecordWriter writer(record, state.source, document.style());
    writer.required("id", state.id);
    writer.integer("stellung", state.position, 0);
    return record;
}

} // namespace

AccessoryStatusFile AccessoryStatusFile::read(const Document& document, Diagnostics& diagnostics) {
    AccessoryStatusFile file;
    file.document = document;
    accessories::checkSection(document, section, "accessory states", diagnostics);
    OnceReporter reporter(diagnostics);
    const accessories::FileVersion version =
        accessories::readRecords(document, recordKeyword, reporter, [&](const Node& record) {
            file.states.push_back(readState(record, reporter));
        });
    file.versionMajor = version.major;
    file.versionMinor = version.minor;
    checkDuplicates(file.states, diagnostics);
    return file;
}

Document AccessoryStatusFile::write() const {
    return accessories::writeRecords(document, {versionMajor, versionMinor}, recordKeyword, states,
                                     writeState);
}

const AccessoryState* AccessoryStatusFile::find(std::int64_t id) const {
    return accessories::findById(states, id);
}

std::string toJson(const AccessoryStatusFile& file) {
    JsonWriter json;
    json.beginObject();
    json.value("file", "magnetartikel.sr2");
    accessories::writeVersionJson(json, {file.versionMajor, file.versionMinor});
    json.beginArray("states");
    for (const AccessoryState& state : file.states) {
        json.beginObject();
        json.value("line", state.lineNumber());
        json.value("id", state.id);
        json.value("position", state.position);
        json.endObject();
    }
    json.endArray();
    json.endObject();
    return json.text();
}

} // namespace stellwerk::cs2config
