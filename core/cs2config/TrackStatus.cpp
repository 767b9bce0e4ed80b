#include "cs2config/TrackStatus.h"

#include "cs2config/TrackFields.h"

#include <map>

namespace stellwerk::cs2config {

namespace {

constexpr std::string_view keyId = "id";
constexpr std::string_view keyState = "zustand";
constexpr std::string_view knownRecords[] = {"version", TrackElementStatus::keyword};
constexpr std::string_view singleRecords[] = {"version"};
constexpr std::string_view elementKeys[] = {keyId, keyState};

TrackElementStatus readEntry(const Node& record, Diagnostics* diagnostics) {
    const TrackFieldReader fields(record, "status element", diagnostics);
    TrackElementStatus entry;
    entry.id = fields.integer(keyId, 0, 0, UINT32_MAX);
    entry.state = fields.integer(keyState, 0, 0, INT32_MAX);
    entry.source = record;
    return entry;
}

std::vector<TrackElementStatus> readEntries(const std::vector<const Node*>& records,
                                            Diagnostics& diagnostics) {
    ReportOnce unknownKeys;
    std::map<std::int64_t, int> lines;
    std::vector<TrackElementStatus> entries;
    entries.reserve(records.size());
    for (const Node* record : records) {
        checkRecordKeys(*record, elementKeys, "status element", unknownKeys, diagnostics);
        if (!findField(*record, keyId))
            diagnostics.warning(record->lineNumber(), "status element without .id", "kept; read as id 0");
        entries.push_back(readEntry(*record, &diagnostics));
        const TrackElementStatus& entry = entries.back();
        if (const auto [other, added] = lines.emplace(entry.id, entry.line()); !added)
            diagnostics.warning(entry.line(),
                                "second status for element " + std::to_string(entry.id) + " (also line " +
                                    std::to_string(other->second) + ")",
                                "both are kept; find() gives the first one");
    }
    return entries;
}

Node writeEntry(const TrackElementStatus& entry, const Document& document) {
    const bool added = isNewRecord(entry.source);
    Node record = editableRecord(entry.source, document, TrackElementStatus::keyword);
    const TrackElementStatus before = readEntry(record, nullptr);
    TrackFieldWriter fields(record, document.style());
    if (added || entry.id != before.id)
        fields.setInteger(keyId, entry.id);
    if (entry.state != before.state)
        fields.setInteger(keyState, entry.state, TrackFieldWriter::Base::Decimal, 0);
    return record;
}

} // namespace

TrackStatusFile TrackStatusFile::read(const Document& document, Diagnostics& diagnostics) {
    TrackStatusFile status;
    status.document = document;
    checkTrackSection(document, section, "a track plan status file", diagnostics);
    checkRecords(document, knownRecords, singleRecords, diagnostics);
    status.version = readTrackVersion(document, &diagnostics);
    status.elements = readEntries(document.records(TrackElementStatus::keyword), diagnostics);
    return status;
}

Document TrackStatusFile::write() const {
    Document out = document;
    writeTrackVersion(out, version);
    writeRecordsIfChanged(out, TrackElementStatus::keyword, elements,
                          [&](const TrackElementStatus& entry) { return writeEntry(entry, out); });
    return out;
}

const TrackElementStatus* TrackStatusFile::find(std::int64_t id) const {
    for (const TrackElementStatus& entry : elements)
        if (entry.id == id)
            return &entry;
    return nullptr;
}

std::string toJson(const TrackStatusFile& status) {
    JsonWriter json;
    json.beginObject();
    json.value("section", status.document.section());
    writeVersionJson(json, status.version);
    json.beginArray("elements");
    for (const TrackElementStatus& entry : status.elements) {
        json.beginObject();
        json.value("line", entry.line());
        json.value("id", entry.id);
        json.value("state", entry.state);
        json.endObject();
    }
    json.endArray();
    json.endObject();
    return json.text();
}

} // namespace stellwerk::cs2config
