#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/JsonWriter.h"
#include "cs2config/LocomotiveValues.h"

#include <initializer_list>
#include <optional>
#include <string_view>
#include <utility>

// File-level pieces shared by lokomotive.cs2, lokomotive.sr2 and the MS2 loco streams: the section
// header, records that may appear once, the `version` record, records nobody knows.
namespace stellwerk::cs2config::loco {

// Warns when the file has a header other than the expected ones.
void checkSection(const Document& document, std::initializer_list<std::string_view> expected,
                  Diagnostics& diagnostics);

// The first record with this keyword; every further one is reported ("the first one is used").
const Node* singleRecord(const Document& document, std::string_view keyword, Diagnostics& diagnostics);

// Notes every top-level record whose keyword is not one of `known`.
void noteUnknownRecords(const Document& document, std::initializer_list<std::string_view> known,
                        Findings& findings);

// `version` with `.major` and `.minor` (a missing one reads as 0).
struct RecordVersion {
    int major = 0;
    int minor = 0;
};
std::optional<RecordVersion> readVersion(const Document& document, Diagnostics& diagnostics,
                                         Findings& findings);

// Writes the record with this keyword (made at the end of the document when missing) through
// `fill(record, fresh)`; removes the keyword's records when `present` is false.
template <class Fill>
void writeSingleRecord(Document& out, std::string_view keyword, bool present, Fill fill);

void writeVersion(Document& out, const std::optional<RecordVersion>& version);

// "version": {"major", "minor"}, or null when the file has none; for each file's own Version type.
template <class Version>
void writeVersionJson(JsonWriter& json, const std::optional<Version>& version) {
    if (version)
        json.beginObject("version").value("major", version->major).value("minor", version->minor).endObject();
    else
        json.null("version");
}

// The first record with this keyword, made at the end of the document when there is none.
Node& recordToWrite(Document& out, std::string_view keyword, bool& fresh);

template <class Fill>
void writeSingleRecord(Document& out, std::string_view keyword, bool present, Fill fill) {
    if (!present) {
        out.replaceRecords(keyword, {});
        return;
    }
    bool fresh = false;
    Node& record = recordToWrite(out, keyword, fresh);
    fill(record, fresh);
}

} // namespace stellwerk::cs2config::loco
