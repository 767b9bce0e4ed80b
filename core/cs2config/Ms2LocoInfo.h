#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/Locomotive.h"

#include <optional>
#include <string>

namespace stellwerk::cs2config {

// How the MS2 text streams are written in the document's examples (8.4, 8.5): two spaces before
// the dots.
LineStyle ms2LineStyle();

// The MS2 stream "lokinfo" (document 8.4): one locomotive with as much of its lokomotive.cs2 record
// as an MS2 needs (uid, name, address, type, mfx uid, acceleration, braking, volume, vmax, vmin),
// its functions as `.fkt` blocks and, for mfx decoders, the `.mfxAdr` block. The text is what a
// station sends; the 8-byte padding of the transport is not part of it.
struct Ms2LocoInfo {
    Document document = Document::create("lokomotive", ms2LineStyle());
    std::optional<Locomotive> locomotive; // the first `lok` record

    static Ms2LocoInfo read(const Document& document, Diagnostics& diagnostics);
    // The lokinfo a station sends for this locomotive of its lokomotive.cs2.
    static Ms2LocoInfo from(const Locomotive& locomotive);
    Document write() const;
};

std::string toJson(const Ms2LocoInfo& info);

} // namespace stellwerk::cs2config
