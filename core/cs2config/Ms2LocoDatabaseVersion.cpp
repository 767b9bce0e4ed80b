#include "cs2config/Ms2LocoDatabaseVersion.h"

#include "cs2config/JsonWriter.h"
#include "cs2config/LocomotiveFieldWriter.h"
#include "cs2config/LocomotiveKeys.h"
#include "cs2config/LocomotiveValues.h"

#include <array>

namespace stellwerk::cs2config {

namespace {

namespace key = locokey;
using loco::FieldWriter;
using loco::Findings;

enum Value : std::size_t { Version, Monat, Jahr, Anzahl };
constexpr std::array<std::string_view, 4> valueKeys{key::ldbVersion, key::monat, key::jahr, key::anzahl};

// The top-level lines of a headerless document as the children of one record, so that the record
// helpers can read and write them; the lines go back into the document afterwards.
class TopLevelLines {
public:
    explicit TopLevelLines(Document& document)
        : document_(document), holder_(Node::entry(0, "", std::nullopt, document.style())) {
        holder_.children() = std::move(document_.topLevel());
    }
    ~TopLevelLines() { document_.topLevel() = std::move(holder_.children()); }
    TopLevelLines(const TopLevelLines&) = delete;
    TopLevelLines& operator=(const TopLevelLines&) = delete;

    Node& record() { return holder_; }

private:
    Document& document_;
    Node holder_;
};

} // namespace

Document Ms2LocoDatabaseVersion::emptyDocument() {
    Diagnostics ignored;
    return Document::parse(".version=0\n.monat=0\n.jahr=0\n.anzahl=0\n", ignored);
}

Ms2LocoDatabaseVersion Ms2LocoDatabaseVersion::read(const Document& document, Diagnostics& diagnostics) {
    Ms2LocoDatabaseVersion result;
    result.document = document;
    Findings findings;
    const loco::RecordLines lines(document.root(), {valueKeys, {}, "ldbver stream"}, diagnostics, findings);
    loco::ValueReader values(diagnostics, loco::TextCoding::Plain);
    result.version = values.number(lines[Version], 0);
    result.month = values.number(lines[Monat], 0);
    result.year = values.number(lines[Jahr], 0);
    result.count = values.number(lines[Anzahl], 0);
    for (std::size_t i = 0; i < valueKeys.size(); ++i)
        if (!lines[i])
            findings.note(Findings::Kind::MissingKey, "." + std::string(valueKeys[i]),
                          "ldbver without '." + std::string(valueKeys[i]) + "'", "read as 0", 0);
    if (lines[Monat] && (result.month < 1 || result.month > 12))
        diagnostics.warning(lines[Monat]->lineNumber(),
                            "month " + std::to_string(result.month) + " is not 1-12", "kept");
    findings.report(diagnostics);
    return result;
}

Document Ms2LocoDatabaseVersion::write() const {
    Document out = document;
    {
        TopLevelLines lines(out);
        FieldWriter fields(lines.record(), out.style(), false);
        fields.number(key::ldbVersion, version, 0, FieldWriter::Base::Decimal);
        fields.number(key::monat, month, 0, FieldWriter::Base::Decimal);
        fields.number(key::jahr, year, 0, FieldWriter::Base::Decimal);
        fields.number(key::anzahl, count, 0, FieldWriter::Base::Decimal);
        loco::keepFinalEnding(lines.record(), out.style());
    }
    return out;
}

std::string toJson(const Ms2LocoDatabaseVersion& version) {
    JsonWriter json;
    json.beginObject()
        .value("kind", "ldbver")
        .value("version", version.version)
        .value("month", version.month)
        .value("year", version.year)
        .value("count", version.count)
        .endObject();
    return json.text();
}

} // namespace stellwerk::cs2config
