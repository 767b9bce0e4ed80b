#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/Node.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// The last position of one accessory as the station saved it (an "artikel" record of
// magnetartikel.sr2): lets a client show the keyboard as it is without switching anything.
struct AccessoryState {
    std::int64_t id = 0;       // .id: keyboard address, as in magnetartikel.cs2
    std::int64_t position = 0; // .stellung, 0 when the line is missing
    Node source;               // the record as read (empty for a new one)

    int lineNumber() const { return source.lineNumber(); }
};

// magnetartikel.sr2, the accessory status file (config-data stream key "magstat"). The protocol document
// does not describe it. Its format here follows the public programs that read or serve it: JCS
// (fransjacobs/model-railway, AccessoryParser.parseAccessoryStatusFile) reads "[magnetartikel]" with
// "artikel" records of `.id` and `.stellung` (a missing `.stellung` meaning 0); RailControl's CS2 HTTP
// server answers /config/magnetartikel.sr2 with "[magnetartikel]", "version", " .minor=1"; GBert's
// can2udp ships a gleisbild.sr2 of that same shape ("[gleisbild]", "version", " .minor=1").
struct AccessoryStatusFile {
    static constexpr std::string_view section = "magnetartikel";
    static constexpr std::string_view recordKeyword = "artikel";

    Document document = Document::create(section);
    std::optional<std::int64_t> versionMajor;
    std::optional<std::int64_t> versionMinor;
    std::vector<AccessoryState> states;

    // Reads every "artikel" record; reports unknown keys and records once, values that are not numbers,
    // missing ids and ids given twice.
    static AccessoryStatusFile read(const Document& document, Diagnostics& diagnostics);
    Document write() const;

    // The state of the accessory with this id, or null.
    const AccessoryState* find(std::int64_t id) const;
};

std::string toJson(const AccessoryStatusFile& file);

} // namespace stellwerk::cs2config
