#include "cs2config/LocomotiveFile.h"

#include "cs2config/LocomotiveFieldWriter.h"
#include "cs2config/LocomotiveKeys.h"
#include "cs2config/LocomotiveRecord.h"
#include "cs2config/LocomotiveSections.h"
#include "cs2config/LocomotiveValues.h"
#include "cs2config/Values.h"

#include <array>
#include <unordered_map>

namespace stellwerk::cs2config {

namespace {

namespace key = locokey;
using loco::FieldWriter;
using loco::Findings;

constexpr std::array<std::string_view, 1> sessionKeys{key::id};

int valueLine(const Locomotive& locomotive, std::string_view valueKey) {
    const Node* line = locomotive.source.find(valueKey);
    return line ? line->lineNumber() : locomotive.source.lineNumber();
}

std::string hex(std::uint32_t value) {
    return formatHex(value);
}

// Reads lokomotive.cs2 record by record and checks what only the whole file shows: duplicate
// identities, traction units that are missing, the CS3-native flavour.
class LocomotiveFileReader {
public:
    LocomotiveFileReader(const Document& document, Diagnostics& diagnostics)
        : document_(document), diagnostics_(diagnostics) {}

    LocomotiveFile read();

private:
    void detectCs3(LocomotiveFile& file);
    void readSession(LocomotiveFile& file);
    void checkDuplicates(const std::vector<Locomotive>& locomotives);
    void checkTraction(const std::vector<Locomotive>& locomotives);
    void reportFindings(const LocomotiveFile& file);

    const Document& document_;
    Diagnostics& diagnostics_;
    Findings findings_;
    std::unordered_map<std::uint32_t, const Locomotive*> byUid_;
    int cs3Line_ = 0;
};

LocomotiveFile LocomotiveFileReader::read() {
    LocomotiveFile file;
    file.document = document_;
    loco::checkSection(document_, {key::section}, diagnostics_);
    detectCs3(file);
    if (const auto version = loco::readVersion(document_, diagnostics_, findings_))
        file.version = LocomotiveFile::Version{version->major, version->minor};
    readSession(file);
    loco::noteUnknownRecords(document_, {key::locomotive, key::version, key::session}, findings_);
    LocomotiveRecordReader reader(diagnostics_, findings_,
                                  file.cs3Native ? loco::TextCoding::Cs3Escaped : loco::TextCoding::Plain);
    const std::vector<const Node*> records = document_.records(key::locomotive);
    file.locomotives.reserve(records.size());
    for (const Node* record : records) {
        file.locomotives.push_back(reader.read(*record));
        if (file.locomotives.back().isEmpty())
            diagnostics_.warning(record->lineNumber(), "empty locomotive record (no name, uid 0)",
                                 "kept unchanged; not a usable locomotive");
    }
    checkDuplicates(file.locomotives);
    checkTraction(file.locomotives);
    reportFindings(file);
    return file;
}

void LocomotiveFileReader::detectCs3(LocomotiveFile& file) {
    for (const Node* record : document_.records(key::locomotive)) {
        if (const Node* line = record->find(key::dectyp); line && !record->find(key::typ)) {
            file.cs3Native = true;
            cs3Line_ = line->lineNumber();
            return;
        }
    }
}

void LocomotiveFileReader::readSession(LocomotiveFile& file) {
    const Node* record = loco::singleRecord(document_, key::session, diagnostics_);
    if (!record)
        return;
    const loco::RecordLines lines(*record, {sessionKeys, {}, "'session' record"}, diagnostics_, findings_);
    file.session = loco::ValueReader(diagnostics_, loco::TextCoding::Plain).number<std::int64_t>(lines[0], 0);
}

void LocomotiveFileReader::checkDuplicates(const std::vector<Locomotive>& locomotives) {
    std::unordered_map<std::uint32_t, const Locomotive*> bySid;
    std::unordered_map<std::uint32_t, const Locomotive*> byMfxUid;
    const auto check = [this](auto& seen, std::uint32_t value, const Locomotive& locomotive,
                              std::string_view what) {
        const auto [first, added] = seen.try_emplace(value, &locomotive);
        if (added)
            return;
        const Locomotive& earlier = *first->second;
        const int line = valueLine(locomotive, what);
        diagnostics_.warning(line,
                             "duplicate " + std::string(what) + " " + hex(value) + ": locomotives " +
                                 loco::describe(earlier.name, valueLine(earlier, what)) + " and " +
                                 loco::describe(locomotive.name, line),
                             "both kept");
    };
    for (const Locomotive& locomotive : locomotives) {
        if (locomotive.isEmpty())
            continue;
        check(byUid_, locomotive.uid, locomotive, key::uid);
        // The SID is assigned to mfx decoders only; other records carry a left-over value.
        if (locomotive.decoder == LocomotiveDecoder::Mfx && locomotive.sid != 0)
            check(bySid, locomotive.sid, locomotive, key::sid);
        if (locomotive.mfxUid != 0 && locomotive.mfxUid != 0xffffffffu)
            check(byMfxUid, locomotive.mfxUid, locomotive, key::mfxuid);
    }
}

void LocomotiveFileReader::checkTraction(const std::vector<Locomotive>& locomotives) {
    for (const Locomotive& locomotive : locomotives) {
        if (locomotive.inTraction != Locomotive::noTraction && !byUid_.contains(locomotive.inTraction))
            diagnostics_.warning(
                valueLine(locomotive, key::inTraktion),
                "locomotive " + loco::nameOf(locomotive.name, locomotive.source.lineNumber()) +
                    " runs in unit " + hex(locomotive.inTraction) + ", which is not in this file",
                "kept");
        for (const TractionMember& member : locomotive.traction)
            if (member.uid != 0 && !byUid_.contains(member.uid))
                diagnostics_.warning(member.source.lineNumber(),
                                     "unit " + loco::nameOf(locomotive.name, locomotive.source.lineNumber()) +
                                         " lists locomotive " + hex(member.uid) +
                                         ", which is not in this file",
                                     "kept");
    }
}

void LocomotiveFileReader::reportFindings(const LocomotiveFile& file) {
    if (!file.cs3Native) {
        findings_.report(diagnostics_);
        return;
    }
    // One diagnostic for the flavour, naming the keys that differ, instead of one per key.
    std::string message = "CS3-native locomotive file ('.dectyp', '#20' escapes), not the CS2 format";
    const auto list = [&message](const std::vector<std::string>& keys, std::string_view title) {
        for (std::size_t i = 0; i < keys.size(); ++i)
            message += (i == 0 ? "; " + std::string(title) + ": " : ", ") + keys[i];
    };
    list(findings_.subjects(Findings::Kind::UnknownKey), "keys the CS2 format does not have");
    list(findings_.subjects(Findings::Kind::MissingKey), "CS2 keys it lacks");
    diagnostics_.warning(cs3Line_, std::move(message),
                         "read as far as it matches the CS2 format; names unescaped; kept unchanged");
    findings_.report(diagnostics_, true);
}

void writeSession(Document& out, const std::optional<std::int64_t>& session) {
    loco::writeSingleRecord(out, key::session, session.has_value(), [&](Node& record, bool fresh) {
        FieldWriter fields(record, out.style(), fresh);
        fields.number<std::int64_t>(key::id, *session, 0, FieldWriter::Base::Decimal,
                                    FieldWriter::Presence::Required);
        loco::keepFinalEnding(record, out.style());
    });
}

} // namespace

LocomotiveFile LocomotiveFile::read(const Document& document, Diagnostics& diagnostics) {
    return LocomotiveFileReader(document, diagnostics).read();
}

Document LocomotiveFile::write() const {
    Document out = document;
    loco::writeVersion(out, version ? std::optional<loco::RecordVersion>({version->major, version->minor})
                                    : std::nullopt);
    writeSession(out, session);
    const LocomotiveRecordWriter writer(out.style(), LocomotiveRecordKind::File,
                                        cs3Native ? loco::TextCoding::Cs3Escaped : loco::TextCoding::Plain);
    std::vector<Node> records;
    records.reserve(locomotives.size());
    for (const Locomotive& locomotive : locomotives)
        records.push_back(writer.write(locomotive));
    out.replaceRecords(key::locomotive, std::move(records));
    return out;
}

const Locomotive* LocomotiveFile::find(std::uint32_t uid) const {
    for (const Locomotive& locomotive : locomotives)
        if (locomotive.uid == uid && !locomotive.isEmpty())
            return &locomotive;
    return nullptr;
}

std::size_t LocomotiveFile::functionCount() const {
    std::size_t count = 0;
    for (const Locomotive& locomotive : locomotives)
        count += locomotive.functions.size();
    return count;
}

} // namespace stellwerk::cs2config
