#include "cs2config/AccessoryStatusFile.h"

#include "cs2config/AccessoryRecordSupport.h"
#include "cs2config/JsonWriter.h"
#include "cs2config/RecordFile.h"

namespace stellwerk::cs2config {

namespace {

using accessories::OnceReporter;
using accessories::RecordReader;
using accessories::RecordWriter;

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
    accessories::firstLineOfEachId(states, [&](const AccessoryState& state, int firstLine) {
        diagnostics.warning(state.lineNumber(),
                            "state of accessory " + std::to_string(state.id) +
                                " given again (first at line " + std::to_string(firstLine) + ")",
                            "both kept; the first one is used");
    });
}

Node writeState(const AccessoryState& state, const Document& document) {
    Node record = accessories::recordFrom(state.source, document, AccessoryStatusFile::recordKeyword);
    RecordWriter writer(record, state.source, document.style());
    writer.required("id", state.id);
    writer.integer("stellung", state.position, 0);
    return record;
}

void writeStateJson(JsonWriter& json, const AccessoryState& state) {
    json.beginObject();
    json.value("line", state.lineNumber());
    json.value("id", state.id);
    json.value("position", state.position);
    json.endObject();
}

constexpr accessories::RecordFileKind<AccessoryStatusFile, AccessoryState> kind{
    .items = &AccessoryStatusFile::states,
    .readAs = "accessory states",
    .fileName = "magnetartikel.sr2",
    .jsonItems = "states",
    .read = readState,
    .write = writeState,
    .writeJson = writeStateJson};

} // namespace

AccessoryStatusFile AccessoryStatusFile::read(const Document& document, Diagnostics& diagnostics) {
    AccessoryStatusFile file = accessories::readRecordFile(kind, document, diagnostics);
    checkDuplicates(file.states, diagnostics);
    return file;
}

Document AccessoryStatusFile::write() const {
    return accessories::writeRecordFile(kind, *this);
}

const AccessoryState* AccessoryStatusFile::find(std::int64_t id) const {
    return accessories::findById(states, id);
}

std::string toJson(const AccessoryStatusFile& file) {
    return accessories::recordFileJson(kind, file);
}

} // namespace stellwerk::cs2config
