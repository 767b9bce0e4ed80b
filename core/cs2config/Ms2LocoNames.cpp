#include "cs2config/Ms2LocoNames.h"

#include "cs2config/JsonWriter.h"
#include "cs2config/LocomotiveFieldWriter.h"
#include "cs2config/LocomotiveKeys.h"
#include "cs2config/LocomotiveSections.h"
#include "cs2config/LocomotiveValues.h"

#include <array>
#include <unordered_map>

namespace stellwerk::cs2config {

namespace {

namespace key = locokey;
using loco::FieldWriter;
using loco::Findings;
using loco::RecordLines;

constexpr std::array<std::string_view, 2> entryKeys{key::nr, key::name};
constexpr std::array<std::string_view, 1> totalKeys{key::wert};

Ms2LocoName readEntry(const Node& record, Diagnostics& diagnostics, Findings& findings) {
    const RecordLines lines(record, {entryKeys, {}, "'lok' record"}, diagnostics, findings);
    loco::ValueReader values(diagnostics, loco::TextCoding::Plain);
    Ms2LocoName entry{values.number(lines[0], 0), values.text(lines[1]), record};
    if (!lines[0])
        findings.note(Findings::Kind::MissingKey, ".nr", "'lok' record without '.nr'", "read as 0",
                      record.lineNumber());
    return entry;
}

void checkEntries(const Ms2LocoNames& names, Diagnostics& diagnostics) {
    std::unordered_map<int, int> firstLine;
    for (const Ms2LocoName& entry : names.entries) {
        const int line = entry.source.lineNumber();
        const auto [first, added] = firstLine.try_emplace(entry.number, line);
        if (!added)
            diagnostics.warning(line,
                                "two entries with '.nr=" + std::to_string(entry.number) + "' (lines " +
                                    std::to_string(first->second) + " and " + std::to_string(line) + ")",
                                "both kept");
        if (names.total && (entry.number < 0 || entry.number >= *names.total))
            diagnostics.warning(line,
                                "entry '.nr=" + std::to_string(entry.number) + "' is outside the " +
                                    std::to_string(*names.total) + " locomotives of 'numloks'",
                                "kept");
    }
}

Node writeEntry(const Ms2LocoName& entry, const LineStyle& style) {
    const bool fresh = !entry.source.isEntry();
    Node record = fresh ? Node::entry(0, key::lok, std::nullopt, style) : entry.source;
    FieldWriter fields(record, style, fresh);
    fields.number(key::nr, entry.number, 0, FieldWriter::Base::Decimal, FieldWriter::Presence::Required);
    fields.text(key::name, entry.name, FieldWriter::Presence::Required);
    loco::keepFinalEnding(record, style);
    return record;
}

} // namespace

Ms2LocoNames Ms2LocoNames::read(const Document& document, Diagnostics& diagnostics) {
    Ms2LocoNames names;
    names.document = document;
    Findings findings;
    loco::checkSection(document, {key::section}, diagnostics);
    loco::noteUnknownRecords(document, {key::lok, key::numloks}, findings);
    for (const Node* record : document.records(key::lok))
        names.entries.push_back(readEntry(*record, diagnostics, findings));
    if (const Node* record = loco::singleRecord(document, key::numloks, diagnostics)) {
        const RecordLines lines(*record, {totalKeys, {}, "'numloks' record"}, diagnostics, findings);
        names.total = loco::ValueReader(diagnostics, loco::TextCoding::Plain).number(lines[0], 0);
    } else {
        diagnostics.warning(0, "no 'numloks' record", "the number of locomotives is unknown");
    }
    checkEntries(names, diagnostics);
    findings.report(diagnostics);
    return names;
}

Document Ms2LocoNames::write() const {
    Document out = document;
    std::vector<Node> records;
    records.reserve(entries.size());
    for (const Ms2LocoName& entry : entries)
        records.push_back(writeEntry(entry, out.style()));
    out.replaceRecords(key::lok, std::move(records));
    loco::writeSingleRecord(out, key::numloks, total.has_value(), [&](Node& record, bool fresh) {
        FieldWriter fields(record, out.style(), fresh);
        fields.number(key::wert, *total, 0, FieldWriter::Base::Decimal, FieldWriter::Presence::Required);
        loco::keepFinalEnding(record, out.style());
    });
    return out;
}

std::string toJson(const Ms2LocoNames& names) {
    JsonWriter json;
    json.beginObject().value("kind", "loknamen");
    if (names.total)
        json.value("total", *names.total);
    else
        json.null("total");
    json.beginArray("entries");
    for (const Ms2LocoName& entry : names.entries)
        json.beginObject().value("number", entry.number).value("name", entry.name).endObject();
    json.endArray().endObject();
    return json.text();
}

} // namespace stellwerk::cs2config
