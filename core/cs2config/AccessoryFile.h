#pragma once

#include "cs2config/AccessoryType.h"
#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/Node.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// One keyboard entry of the station (an "artikel" record of magnetartikel.cs2 or of the MS2's "maginfo"
// stream): a turnout, signal, uncoupler or turntable and where it is on the keyboard.
struct Accessory {
    std::int64_t id = 0;                      // .id: 1-based keyboard address of its first output
    std::string name;                         // .name
    std::string type;                         // .typ: "rechtsweiche", "lichtsignal_HP01", ...
    std::int64_t position = 0;                // .stellung, 0 when the line is missing
    std::optional<std::int64_t> switchTimeMs; // .schaltzeit
    bool secondOutput = false;                // .ungerade=1: a one-output article on the second output
    std::string decoder;                      // .decoder: decoder kind ("mehr_alt", "mehr_neu", "ein_neu")
    std::string protocol;                     // .dectyp: "mm2" or "dcc"
    Node source;                              // the record as read (empty for a new accessory)

    // The document's description of `type`, or null for a type it does not list.
    const AccessoryTypeInfo* typeInfo() const { return findAccessoryType(type); }
    // Keyboard addresses taken from `id` on (1 for unknown types).
    int addressCount() const;
    int lineNumber() const { return source.lineNumber(); }
};

// magnetartikel.cs2: every accessory of the station in keyboard order, and the file it came from so that
// writing keeps what the model does not know about.
struct AccessoryFile {
    static constexpr std::string_view section = "magnetartikel";
    static constexpr std::string_view recordKeyword = "artikel";

    Document document = Document::create(section);
    std::optional<std::int64_t> versionMajor;
    std::optional<std::int64_t> versionMinor;
    std::vector<Accessory> accessories;

    // Reads every "artikel" record; reports unknown types and keys once, values that are not numbers,
    // missing ids, duplicate ids and articles whose addresses overlap.
    static AccessoryFile read(const Document& document, Diagnostics& diagnostics);
    // The source document with each accessory's record updated; unchanged accessories keep their bytes.
    Document write() const;
};

// The MS2's "maginfo" stream (document 8.6): the same records cut down to id, name, typ, schaltzeit and
// dectyp, without a version record. AccessoryFile::read reads it as it is.
Document writeAccessoryInfo(const std::vector<Accessory>& accessories, LineStyle style = {"  ", "\n"});

// `stellwerk-cli cs2 json`: the accessories with their types' address and position counts.
std::string toJson(const AccessoryFile& file);

} // namespace stellwerk::cs2config
