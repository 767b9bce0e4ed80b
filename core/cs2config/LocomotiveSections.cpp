#include "cs2config/LocomotiveSections.h"

#include "cs2config/LocomotiveFieldWriter.h"
#include "cs2config/LocomotiveKeys.h"

#include <algorithm>
#include <array>

namespace stellwerk::cs2config::loco {

namespace {

namespace key = locokey;

constexpr std::array<std::string_view, 2> versionKeys{key::major, key::minor};

} // namespace

void checkSection(const Document& document, std::initializer_list<std::string_view> expected,
                  Diagnostics& diagnostics) {
    if (!document.hasHeader() ||
        std::find(expected.begin(), expected.end(), document.section()) != expected.end())
        return;
    int line = 0;
    for (const Node& node : document.topLevel())
        if (node.kind() == Node::Kind::Header && line == 0)
            line = node.lineNumber();
    diagnostics.warning(line,
                        "section '[" + std::string(document.section()) + "]' is not '[" +
                            std::string(*expected.begin()) + "]'",
                        "read anyway");
}

const Node* singleRecord(const Document& document, std::string_view keyword, Diagnostics& diagnostics) {
    const std::vector<const Node*> records = document.records(keyword);
    for (std::size_t i = 1; i < records.size(); ++i)
        diagnostics.warning(records[i]->lineNumber(),
                            "second '" + std::string(keyword) + "' record (lines " +
                                std::to_string(records.front()->lineNumber()) + " and " +
                                std::to_string(records[i]->lineNumber()) + "); the file has one",
                            "the first one is used; both kept");
    return records.empty() ? nullptr : records.front();
}

void noteUnknownRecords(const Document& document, std::initializer_list<std::string_view> known,
                        Findings& findings) {
    for (const Node& node : document.topLevel()) {
        if (!node.isEntry() || std::find(known.begin(), known.end(), node.key()) != known.end())
            continue;
        const std::string label = keyLabel(node);
        findings.note(Findings::Kind::UnknownKey, label, "unknown record '" + label + "'", "kept unchanged",
                      node.lineNumber());
    }
}

std::optional<RecordVersion> readVersion(const Document& document, Diagnostics& diagnostics,
                                         Findings& findings) {
    const Node* record = singleRecord(document, key::version, diagnostics);
    if (!record)
        return std::nullopt;
    const RecordLines lines(*record, {versionKeys, {}, "'version' record"}, diagnostics, findings);
    ValueReader values(diagnostics, TextCoding::Plain);
    return RecordVersion{values.number(lines[0], 0), values.number(lines[1], 0)};
}

Node& recordToWrite(Document& out, std::string_view keyword, bool& fresh) {
    if (Node* existing = out.record(keyword)) {
        fresh = false;
        return *existing;
    }
    std::vector<Node> created;
    created.push_back(out.newRecord(keyword));
    out.replaceRecords(keyword, std::move(created));
    fresh = true;
    return *out.record(keyword);
}

void writeVersion(Document& out, const std::optional<RecordVersion>& version) {
    writeSingleRecord(out, key::version, version.has_value(), [&](Node& record, bool fresh) {
        FieldWriter fields(record, out.style(), fresh);
        fields.number(key::major, version->major, 0, FieldWriter::Base::Decimal,
                      FieldWriter::Presence::Required);
        fields.number(key::minor, version->minor, 0, FieldWriter::Base::Decimal,
                      FieldWriter::Presence::Required);
        keepFinalEnding(record, out.style());
    });
}

} // namespace stellwerk::cs2config::loco
