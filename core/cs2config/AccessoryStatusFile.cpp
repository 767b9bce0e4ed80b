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
    if (document.hasHeader() && document.section() != section)
        diagnostics.warning(0, "section [" + std::string(document.section()) + "] instead of [magnetartikel]",
                            "read as accessory states");
    OnceReporter reporter(diagnostics);
    const accessories::FileVersion version = accessories::readVersion(document, reporter);
    file.versionMajor = version.major;
    file.versionMinor = version.minor;
    for (const Node& node : document.topLevel()) {
        if (!node.isEntry())
            continue;
        if (node.level() > 0)
            reporter.strayLine(node);
        else if (node.key() == recordKeyword)
            file.states.push_back(readState(node, reporter));
        else if (node.key() != "version")
            reporter.unknownRecord(node);
    }
    checkDuplicates(file.states, diagnostics);
    return file;
}

Document AccessoryStatusFile::write() const {
    Document out = document;
    accessories::writeVersion(out, {versionMajor, versionMinor});
    std::vector<Node> records;
    records.reserve(states.size());
    for (const AccessoryState& state : states)
        records.push_back(writeState(state, out));
    out.replaceRecords(recordKeyword, std::move(records));
    return out;
}

const AccessoryState* AccessoryStatusFile::find(std::int64_t id) const {
    for (const AccessoryState& state : states)
        if (state.id == id)
            return &state;
    return nullptr;
}

std::string toJson(const AccessoryStatusFile& file) {
    JsonWriter json;
    json.beginObject();
    json.value("file", "magnetartikel.sr2");
    json.beginObject("version");
    writeOptional(json, "major", file.versionMajor);
    writeOptional(json, "minor", file.versionMinor);
    json.endObject();
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
