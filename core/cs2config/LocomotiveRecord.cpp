#include "cs2config/LocomotiveRecord.h"

#include "cs2config/LocomotiveKeys.h"
#include "cs2config/Text.h"

#include <algorithm>
#include <array>
#include <unordered_map>

namespace stellwerk::cs2config {

namespace {

using loco::FieldWriter;
using loco::Findings;
using loco::RecordLines;
using Base = FieldWriter::Base;
using Presence = FieldWriter::Presence;
namespace key = locokey;

// The value keys of a locomotive record, in the order of the table below.
enum Value : std::size_t {
    Uid,
    Name,
    Vorname,
    Adresse,
    Typ,
    Dectyp,
    Sid,
    Mfxuid,
    Icon,
    Symbol,
    Av,
    Bv,
    Volume,
    Progmask,
    Velocity,
    Richtung,
    Tachomax,
    Vmax,
    Vmin,
    Xprot,
    Xprotokoll,
    Mfxtyp,
    InTraktion,
    ValueCount
};

constexpr std::array<std::string_view, ValueCount> valueKeys{
    key::uid,    key::name,     key::vorname,    key::adresse,  key::typ,       key::dectyp,
    key::sid,    key::mfxuid,   key::icon,       key::symbol,   key::av,        key::bv,
    key::volume, key::progmask, key::velocity,   key::richtung, key::tachomax,  key::vmax,
    key::vmin,   key::xprot,    key::xprotokoll, key::mfxtyp,   key::inTraktion};
static_assert(ValueCount <= RecordLines::maxKeys);

constexpr std::array<std::string_view, 6> blockKeys{key::funktionen, key::funktionen2, key::fkt,
                                                    key::traktion,   key::prg,         key::mfxAdr};

enum FunctionValue : std::size_t { Nr, FunctionTyp, Dauer, Wert, Vorwaerts, Rueckwaerts };
constexpr std::array<std::string_view, 6> functionKeys{key::nr,   key::typ,       key::dauer,
                                                       key::wert, key::vorwaerts, key::rueckwaerts};

enum CvValue : std::size_t { CvAdresse, CvName, CvWert, CvMaske };
constexpr std::array<std::string_view, 4> cvKeys{key::adresse, key::name, key::wert, key::maske};

enum MfxValue : std::size_t { Target, MfxName, Addr, Xcel, Speedtable, MfxVolume, Numfunc, Func };
constexpr std::array<std::string_view, 8> mfxKeys{key::target,     key::name,   key::addr,    key::xcel,
                                                  key::speedtable, key::volume, key::numfunc, key::func};

enum TractionValue : std::size_t { TractionLok, Lokname };
constexpr std::array<std::string_view, 2> tractionKeys{key::tractionLok, key::lokname};

bool isFunctionBlock(std::string_view blockKey) {
    return blockKey == key::funktionen || blockKey == key::funktionen2 || blockKey == key::fkt;
}

std::string locomotiveName(const Locomotive& locomotive) {
    return loco::nameOf(locomotive.name, locomotive.source.lineNumber());
}

} // namespace

LocomotiveRecordReader::LocomotiveRecordReader(Diagnostics& diagnostics, loco::Findings& findings,
                                               loco::TextCoding coding)
    : diagnostics_(diagnostics), findings_(findings), values_(diagnostics, coding) {}

Locomotive LocomotiveRecordReader::read(const Node& record) {
    Locomotive locomotive;
    locomotive.source = record;
    readValues(record, locomotive);
    readBlocks(record, locomotive);
    if (!locomotive.isEmpty()) {
        checkRequired(record);
        checkFunctions(locomotive);
    }
    return locomotive;
}

void LocomotiveRecordReader::readValues(const Node& record, Locomotive& locomotive) {
    const RecordLines lines(record, {valueKeys, blockKeys, "locomotive record"}, diagnostics_, findings_);
    locomotive.uid = values_.number<std::uint32_t>(lines[Uid], 0);
    locomotive.name = values_.text(lines[Name]);
    locomotive.previousName = values_.text(lines[Vorname]);
    locomotive.address = values_.number<std::uint32_t>(lines[Adresse], 0);
    readDecoder(lines.either(Typ, Dectyp), locomotive);
    locomotive.sid = values_.number<std::uint32_t>(lines[Sid], 0);
    locomotive.mfxUid = values_.number<std::uint32_t>(lines[Mfxuid], 0);
    locomotive.icon = values_.text(lines[Icon]);
    locomotive.symbol = values_.number(lines[Symbol], 0);
    locomotive.acceleration = values_.number(lines[Av], 0);
    locomotive.braking = values_.number(lines[Bv], 0);
    locomotive.volume = values_.number(lines[Volume], 0);
    locomotive.programmingMask = values_.number(lines[Progmask], 0);
    locomotive.velocity = values_.number(lines[Velocity], 0);
    readDirection(lines[Richtung], locomotive);
    locomotive.tachoMax = values_.number(lines[Tachomax], 0);
    locomotive.vMax = values_.number(lines[Vmax], 0);
    locomotive.vMin = values_.number(lines[Vmin], 0);
    locomotive.extendedProtocol = values_.number(lines.either(Xprot, Xprotokoll), 0);
    locomotive.mfxType = values_.number(lines[Mfxtyp], 0);
    locomotive.inTraction = values_.number<std::uint32_t>(lines[InTraktion], Locomotive::noTraction);
}

void LocomotiveRecordReader::readDecoder(const Node* line, Locomotive& locomotive) {
    const std::string text(trimmed(values_.text(line)));
    locomotive.decoder = decoderFromName(text);
    if (locomotive.decoder != LocomotiveDecoder::Unknown)
        return;
    locomotive.decoderText = text;
    findings_.note(Findings::Kind::Other, text, "unknown decoder type " + quoteForMessage(text),
                   "kept as written", line->lineNumber());
}

void LocomotiveRecordReader::readDirection(const Node* line, Locomotive& locomotive) {
    const loco::ReadValue<TravelDirection> read = loco::readDirection(line);
    locomotive.direction = read.value;
    if (read.problem != loco::ValueProblem::NotANumber && read.problem != loco::ValueProblem::OutOfRange)
        return;
    const std::string_view value = trimmed(line->value());
    const bool notSet = value == "-1" || value == "4294967295";
    findings_.note(Findings::Kind::Other, std::string(value),
                   "direction '.richtung=" + std::string(value.substr(0, 20)) + "' is " +
                       (notSet ? "-1 (not set)" : "neither 0 (forward) nor 1 (backward)"),
                   "read as unknown; kept unchanged", line->lineNumber());
}

void LocomotiveRecordReader::readBlocks(const Node& record, Locomotive& locomotive) {
    for (const Node& block : record.children()) {
        if (!block.isEntry())
            continue;
        const std::string_view blockKey = block.key();
        if (isFunctionBlock(blockKey)) {
            locomotive.functions.push_back(readFunction(block));
        } else if (blockKey == key::traktion) {
            locomotive.traction.push_back(readTractionMember(block));
        } else if (blockKey == key::prg) {
            locomotive.cvRows.push_back(readCvRow(block));
        } else if (blockKey == key::mfxAdr) {
            if (!locomotive.mfxAddress)
                locomotive.mfxAddress = readMfxAddress(block);
            else
                diagnostics_.warning(block.lineNumber(),
                                     "second '.mfxAdr' block in locomotive " + locomotiveName(locomotive),
                                     "the first one is used; both kept");
        }
    }
}

Function LocomotiveRecordReader::readFunction(const Node& block) {
    const RecordLines lines(block, {functionKeys, {}, "function block"}, diagnostics_, findings_);
    Function function;
    function.number = values_.number(lines[Nr], -1);
    function.icon = values_.number(lines[FunctionTyp], 0);
    function.duration = values_.number(lines[Dauer], 0);
    function.value = values_.number(lines[Wert], 0);
    function.source = block;
    if (!lines[Nr])
        findings_.note(Findings::Kind::Other, {}, "function block without '..nr'",
                       "kept unchanged; not numbered", block.lineNumber());
    if (function.trigger() == FunctionTrigger::Unknown)
        findings_.note(Findings::Kind::Other, {},
                       "function duration '..dauer=" + std::to_string(function.duration) +
                           "' is neither 0, -1 nor a time",
                       "kept unchanged", lines[Dauer]->lineNumber());
    return function;
}

CvRow LocomotiveRecordReader::readCvRow(const Node& block) {
    const RecordLines lines(block, {cvKeys, {}, "'.prg' block"}, diagnostics_, findings_);
    CvRow row;
    row.cv = values_.number(lines[CvAdresse], 0);
    row.name = values_.text(lines[CvName]);
    row.value = values_.number(lines[CvWert], 0);
    row.mask = values_.number(lines[CvMaske], 0);
    row.source = block;
    return row;
}

MfxAddress LocomotiveRecordReader::readMfxAddress(const Node& block) {
    const RecordLines lines(block, {mfxKeys, {}, "'.mfxAdr' block"}, diagnostics_, findings_);
    MfxAddress mfx;
    mfx.target = values_.number(lines[Target], 0);
    mfx.name = values_.number(lines[MfxName], 0);
    mfx.address = values_.number(lines[Addr], 0);
    mfx.acceleration = values_.number(lines[Xcel], 0);
    mfx.speedTable = values_.number(lines[Speedtable], 0);
    mfx.volume = values_.number(lines[MfxVolume], 0);
    mfx.functionCount = values_.number(lines[Numfunc], 0);
    mfx.functions = values_.number(lines[Func], 0);
    mfx.source = block;
    return mfx;
}

TractionMember LocomotiveRecordReader::readTractionMember(const Node& block) {
    const RecordLines lines(block, {tractionKeys, {}, "'.traktion' block"}, diagnostics_, findings_);
    TractionMember member;
    member.uid = values_.number<std::uint32_t>(lines[TractionLok], 0);
    member.name = values_.text(lines[Lokname]);
    member.source = block;
    if (!lines[TractionLok])
        findings_.note(Findings::Kind::Other, {}, "'.traktion' block without '..lok'", "kept unchanged",
                       block.lineNumber());
    return member;
}

void LocomotiveRecordReader::checkFunctions(const Locomotive& locomotive) {
    std::unordered_map<int, int> firstLine;
    for (const Function& function : locomotive.functions) {
        const int line = function.source.lineNumber();
        if (function.number < 0)
            continue;
        const std::string label = "F" + std::to_string(function.number);
        if (function.number > 31)
            diagnostics_.warning(line,
                                 "function " + label + " of locomotive " + locomotiveName(locomotive) +
                                     " is outside F0-F31",
                                 "kept");
        else if (function.number < 16 && function.source.key() == key::funktionen2)
            diagnostics_.warning(line, label + " is in a '.funktionen_2' block, which holds F16-F31",
                                 "kept as " + label);
        const auto [first, added] = firstLine.try_emplace(function.number, line);
        if (!added)
            diagnostics_.warning(line,
                                 label + " appears twice in locomotive " + locomotiveName(locomotive) +
                                     " (lines " + std::to_string(first->second) + " and " +
                                     std::to_string(line) + ")",
                                 "both kept");
    }
}

void LocomotiveRecordReader::checkRequired(const Node& record) {
    const auto require = [&](std::string_view wanted, std::string_view alternative, std::string_view readAs) {
        if (record.find(wanted) || (!alternative.empty() && record.find(alternative)))
            return;
        findings_.note(Findings::Kind::MissingKey, "." + std::string(wanted),
                       "locomotive record without '." + std::string(wanted) + "'",
                       "read as " + std::string(readAs), record.lineNumber());
    };
    require(key::uid, {}, "0");
    require(key::name, {}, "an empty name");
    require(key::adresse, {}, "0");
    require(key::typ, key::dectyp, "no decoder type");
}

LocomotiveRecordWriter::LocomotiveRecordWriter(const LineStyle& style, LocomotiveRecordKind kind,
                                               loco::TextCoding coding)
    : style_(style), kind_(kind), coding_(coding) {}

Node LocomotiveRecordWriter::write(const Locomotive& locomotive) const {
    const bool fresh = !locomotive.source.isEntry();
    const std::string_view keyword = kind_ == LocomotiveRecordKind::File ? key::locomotive : key::lok;
    Node record = fresh ? Node::entry(0, keyword, std::nullopt, style_) : locomotive.source;
    writeValues(record, locomotive, fresh);
    writeFunctions(record, locomotive);
    if (kind_ == LocomotiveRecordKind::File) {
        writeTraction(record, locomotive);
        writeCvRows(record, locomotive);
    }
    writeMfxAddress(record, locomotive);
    loco::keepFinalEnding(record, style_);
    return record;
}

void LocomotiveRecordWriter::writeValues(Node& record, const Locomotive& locomotive, bool fresh) const {
    FieldWriter fields(record, style_, fresh, coding_);
    const bool file = kind_ == LocomotiveRecordKind::File;
    fields.number(key::uid, locomotive.uid, 0u, Base::Hex, Presence::Required);
    fields.text(key::name, locomotive.name, Presence::Required);
    if (file)
        fields.text(key::vorname, locomotive.previousName);
    fields.number(key::adresse, locomotive.address, 0u, Base::Hex, Presence::Required);
    fields.decoder(loco::keyInUse(record, key::typ, key::dectyp), locomotive.decoder, locomotive.decoderText);
    if (file)
        fields.number(key::sid, locomotive.sid, 0u, Base::Hex);
    fields.number(key::mfxuid, locomotive.mfxUid, 0u, Base::Hex);
    if (file) {
        fields.text(key::icon, locomotive.icon);
        fields.number(key::symbol, locomotive.symbol, 0, Base::Decimal);
    }
    fields.number(key::av, locomotive.acceleration, 0, Base::Decimal);
    fields.number(key::bv, locomotive.braking, 0, Base::Decimal);
    fields.number(key::volume, locomotive.volume, 0, Base::Decimal);
    if (file)
        writeFileValues(fields, record, locomotive);
    else {
        fields.number(key::vmax, locomotive.vMax, 0, Base::Decimal);
        fields.number(key::vmin, locomotive.vMin, 0, Base::Decimal);
    }
}

void LocomotiveRecordWriter::writeFileValues(FieldWriter& fields, const Node& record,
                                             const Locomotive& locomotive) const {
    fields.number(key::progmask, locomotive.programmingMask, 0, Base::Hex);
    fields.number(key::velocity, locomotive.velocity, 0, Base::Decimal);
    fields.direction(key::richtung, locomotive.direction);
    fields.number(key::tachomax, locomotive.tachoMax, 0, Base::Decimal);
    fields.number(key::vmax, locomotive.vMax, 0, Base::Decimal);
    fields.number(key::vmin, locomotive.vMin, 0, Base::Decimal);
    fields.number(loco::keyInUse(record, key::xprot, key::xprotokoll), locomotive.extendedProtocol, 0,
                  Base::Decimal);
    fields.number(key::mfxtyp, locomotive.mfxType, 0, Base::Decimal);
    fields.number(key::inTraktion, locomotive.inTraction, Locomotive::noTraction, Base::Hex);
}

Node LocomotiveRecordWriter::block(const Node& source, std::string_view blockKey) const {
    return source.isEntry() ? source : Node::entry(1, blockKey, std::nullopt, style_);
}

std::string_view LocomotiveRecordWriter::newFunctionKey(const Node& record, const Function& function) const {
    if (kind_ == LocomotiveRecordKind::LokInfo)
        return key::fkt;
    return function.number >= 16 && record.find(key::funktionen2) ? key::funktionen2 : key::funktionen;
}

void LocomotiveRecordWriter::writeFunctions(Node& record, const Locomotive& locomotive) const {
    std::vector<Node> blocks;
    blocks.reserve(locomotive.functions.size());
    for (const Function& function : locomotive.functions) {
        Node written = block(function.source, newFunctionKey(record, function));
        FieldWriter fields(written, style_, !function.source.isEntry());
        fields.number(key::nr, function.number, -1, Base::Decimal, Presence::Required);
        fields.number(key::typ, function.icon, 0, Base::Decimal);
        fields.number(key::dauer, function.duration, 0, Base::Decimal);
        fields.number(key::wert, function.value, 0, Base::Decimal);
        blocks.push_back(std::move(written));
    }
    loco::replaceBlocks(record, {key::funktionen, key::funktionen2, key::fkt}, std::move(blocks));
}

void LocomotiveRecordWriter::writeTraction(Node& record, const Locomotive& locomotive) const {
    std::vector<Node> blocks;
    for (const TractionMember& member : locomotive.traction) {
        Node written = block(member.source, key::traktion);
        FieldWriter fields(written, style_, !member.source.isEntry(), coding_);
        fields.number(key::tractionLok, member.uid, 0u, Base::Hex, Presence::Required);
        fields.text(key::lokname, member.name, Presence::Required);
        blocks.push_back(std::move(written));
    }
    loco::replaceBlocks(record, {key::traktion}, std::move(blocks));
}

void LocomotiveRecordWriter::writeCvRows(Node& record, const Locomotive& locomotive) const {
    std::vector<Node> blocks;
    for (const CvRow& row : locomotive.cvRows) {
        Node written = block(row.source, key::prg);
        FieldWriter fields(written, style_, !row.source.isEntry(), coding_);
        fields.number(key::adresse, row.cv, 0, Base::Decimal, Presence::Required);
        fields.text(key::name, row.name, Presence::Required);
        fields.number(key::wert, row.value, 0, Base::Decimal, Presence::Required);
        fields.number(key::maske, row.mask, 0, Base::Decimal, Presence::Required);
        blocks.push_back(std::move(written));
    }
    loco::replaceBlocks(record, {key::prg}, std::move(blocks));
}

void LocomotiveRecordWriter::writeMfxAddress(Node& record, const Locomotive& locomotive) const {
    std::vector<Node>& children = record.children();
    const auto first = std::find_if(children.begin(), children.end(), [](const Node& child) {
        return child.isEntry() && child.key() == key::mfxAdr;
    });
    if (!locomotive.mfxAddress) {
        if (first != children.end())
            children.erase(first);
        return;
    }
    const MfxAddress& mfx = *locomotive.mfxAddress;
    Node written = block(mfx.source, key::mfxAdr);
    FieldWriter fields(written, style_, !mfx.source.isEntry());
    fields.number(key::target, mfx.target, 0, Base::Decimal, Presence::Required);
    fields.number(key::name, mfx.name, 0, Base::Decimal, Presence::Required);
    fields.number(key::addr, mfx.address, 0, Base::Decimal, Presence::Required);
    fields.number(key::xcel, mfx.acceleration, 0, Base::Decimal, Presence::Required);
    fields.number(key::speedtable, mfx.speedTable, 0, Base::Decimal, Presence::Required);
    fields.number(key::volume, mfx.volume, 0, Base::Decimal, Presence::Required);
    fields.number(key::numfunc, mfx.functionCount, 0, Base::Decimal, Presence::Required);
    fields.number(key::func, mfx.functions, 0, Base::Decimal, Presence::Required);
    if (first != children.end())
        *first = std::move(written);
    else
        children.push_back(std::move(written));
}

} // namespace stellwerk::cs2config
