#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Locomotive.h"
#include "cs2config/LocomotiveFieldWriter.h"
#include "cs2config/LocomotiveValues.h"
#include "cs2config/Node.h"

namespace stellwerk::cs2config {

// Which flavour of locomotive record: a `lokomotive` record of lokomotive.cs2 (all fields,
// `.funktionen` blocks) or the `lok` record of an MS2 lokinfo stream (document 8.4: a subset of the
// fields, `.fkt` blocks).
enum class LocomotiveRecordKind : std::uint8_t { File, LokInfo };

// Reads one locomotive record into a Locomotive and reports, at its line, whatever it cannot read.
// Keys it does not know go to the findings (reported once per file by the caller).
class LocomotiveRecordReader {
public:
    LocomotiveRecordReader(Diagnostics& diagnostics, loco::Findings& findings, loco::TextCoding coding);

    Locomotive read(const Node& record);

private:
    void readValues(const Node& record, Locomotive& locomotive);
    void readDecoder(const Node* line, Locomotive& locomotive);
    void readDirection(const Node* line, Locomotive& locomotive);
    void readBlocks(const Node& record, Locomotive& locomotive);
    Function readFunction(const Node& block);
    CvRow readCvRow(const Node& block);
    MfxAddress readMfxAddress(const Node& block);
    TractionMember readTractionMember(const Node& block);
    void checkFunctions(const Locomotive& locomotive);
    void checkRequired(const Node& record);

    Diagnostics& diagnostics_;
    loco::Findings& findings_;
    loco::ValueReader values_;
};

// Writes a Locomotive into its record: a changed value rewrites its own line, everything else stays
// as read (unknown keys, order, spacing, "0x05"-style numbers). A locomotive without a source record
// gets a new one in the given style.
class LocomotiveRecordWriter {
public:
    LocomotiveRecordWriter(const LineStyle& style, LocomotiveRecordKind kind, loco::TextCoding coding);

    Node write(const Locomotive& locomotive) const;

private:
    void writeValues(Node& record, const Locomotive& locomotive, bool fresh) const;
    void writeFileValues(loco::FieldWriter& fields, const Node& record, const Locomotive& locomotive) const;
    void writeFunctions(Node& record, const Locomotive& locomotive) const;
    void writeTraction(Node& record, const Locomotive& locomotive) const;
    void writeCvRows(Node& record, const Locomotive& locomotive) const;
    void writeMfxAddress(Node& record, const Locomotive& locomotive) const;
    std::string_view newFunctionKey(const Node& record, const Function& function) const;
    Node block(const Node& source, std::string_view key) const;

    LineStyle style_;
    LocomotiveRecordKind kind_;
    loco::TextCoding coding_;
};

} // namespace stellwerk::cs2config
