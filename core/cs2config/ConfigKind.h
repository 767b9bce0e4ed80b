#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"

#include <optional>
#include <string_view>

namespace stellwerk::cs2config {

// What a file of the CS2 family holds, recognised from its header, its records and its name.
enum class ConfigKind {
    NotConfiguration, // not a .cs2 file at all
    Unknown,          // a .cs2 document of a section Stellwerk has no model for
    Locomotives,      // lokomotive.cs2
    LocomotiveStatus, // lokomotive.sr2
    LocoInfo,         // the MS2's lokinfo stream: one locomotive
    LocoNames,        // the MS2's loknamen / lokliste stream
    LocoDbVersion,    // the MS2's ldbver stream
    Accessories,      // magnetartikel.cs2 (also the MS2's maginfo stream)
    AccessoryStatus,  // magnetartikel.sr2
    Routes,           // fahrstrassen.cs2
    TrackPlan,        // gleisbild.cs2
    TrackPage,        // gleisbilder/<name>.cs2, gbs-<n>
    TrackStatus,      // gleisbild.sr2
};

std::string_view kindName(ConfigKind kind);

// The kind a file's name and place say it is: "lokomotive.cs2", "magnetartikel.sr2", "gleisbild.cs2",
// a .cs2 file in a "gleisbilder" folder, "gbs-3.cs2". `path` may be a bare name or a path; nullopt when
// the name says nothing.
std::optional<ConfigKind> configKindByName(std::string_view path);

// The one place that decides what a file is (`cs2 check`, `cs2 json`, a layout folder, the app): the
// header decides; a file whose header is missing or unreadable, or names a section Stellwerk does not
// know, is read as what its name says, with a warning in `diagnostics` when the header is missing.
ConfigKind recogniseConfigKind(const Document& document, std::string_view path, Diagnostics& diagnostics);

} // namespace stellwerk::cs2config
