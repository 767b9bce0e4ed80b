#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/Ms2LocoInfo.h"
#include "cs2config/Node.h"

#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// One line of the MS2's scrolling loco list: the locomotive's place in the station's list and its name.
struct Ms2LocoName {
    int number = 0; // .nr
    std::string name;
    Node source;
};

// The MS2 streams "loknamen" (document 8.5) and "lokliste": the part of the station's loco list the
// MS2 asked for ("<first> <count>"), as `lok` records with `.nr` and `.name`, and how many
// locomotives the station has in all (`numloks` `.wert`).
struct Ms2LocoNames {
    Document document = Document::create("lokomotive", ms2LineStyle());
    std::vector<Ms2LocoName> entries;
    std::optional<int> total; // numloks .wert

    static Ms2LocoNames read(const Document& document, Diagnostics& diagnostics);
    Document write() const;
};

std::string toJson(const Ms2LocoNames& names);

} // namespace stellwerk::cs2config
