#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/Locomotive.h"
#include "cs2config/Node.h"

#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// The state of one function key in the status file.
struct FunctionState {
    int number = -1; // ..nr
    int value = 0;   // ..wert (missing = off)
    Node source;
};

// What the station remembers of one locomotive between sessions: speed, direction, function states.
// The locomotive is identified by its name, as in lokomotive.cs2.
struct LocomotiveState {
    std::string name;                                     // .name
    int velocity = 0;                                     // .velocity (missing = 0)
    TravelDirection direction = TravelDirection::Forward; // .richtung (missing = 0, forward)
    std::vector<FunctionState> functions;                 // .funktionen blocks
    Node source;

    const FunctionState* function(int number) const;
};

// lokomotive.sr2, the loco status file a CS2 sends for the stream keys `lokstat`/`loksstat`.
// The document does not describe it. Its format here follows mrsystem (a CS2 emulator by Michael
// Bernstein; its lokstatus.c writes and reads the file): a `[lokomotive]` section, `version` with
// `.major=0 .minor=1`, then per locomotive a `lokomotive` record with `.name`, `.velocity` and
// `.richtung` (both left out when 0) and one `.funktionen` block per function with `..nr` and
// `..wert` (left out when 0). RailControl serves a `[lokstatus]` section; both headers are read.
struct LocomotiveStateFile {
    struct Version {
        int major = 0;
        int minor = 1;
    };

    Document document = Document::create("lokomotive");
    std::optional<Version> version;
    std::vector<LocomotiveState> locomotives;

    static LocomotiveStateFile read(const Document& document, Diagnostics& diagnostics);
    Document write() const;

    // The state of the locomotive with this name (the first one when names repeat), or null.
    const LocomotiveState* find(std::string_view name) const;
};

std::string toJson(const LocomotiveStateFile& file);

} // namespace stellwerk::cs2config
