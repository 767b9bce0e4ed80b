#include "cs2config/ConfigStreamKeys.h"

#include <algorithm>
#include <array>

namespace stellwerk::cs2config {
namespace {

using enum FollowUp;
using enum StreamFormat;

constexpr std::string_view PageKey = "gbs-#";

constexpr std::array<ConfigFileKey, 19> Keys{{
    {"lokinfo", "lokinfo.cs2", "MS2", LocoName, Ms2Text, "data of one loco"},
    {"loknamen", "loknamen.cs2", "MS2", Range, Ms2Text, "names of n locos and the total count"},
    {"maginfo", "maginfo.cs2", "MS2", Range, Ms2Text, "data of n accessories"},
    {"lokdb", "lokdb.bin", "MS2", None, Binary, "loco database"},
    {"lang", "lang.bin", "MS2", None, Binary, "language file"},
    {"ldbver", "ldbver.cs2", "MS2", None, Ms2Text, "version of the loco database"},
    {"langver", "langver.cs2", "MS2", None, Ms2Text, "version of the language file"},
    {"loks", "lokomotive.cs2", "CS2", None, Compressed, "complete loco list"},
    {"mags", "magnetartikel.cs2", "CS2", None, Compressed, "complete accessory configuration"},
    {"gbs", "gleisbild.cs2", "CS2", None, Compressed, "track plan index"},
    {PageKey, "gbs-#.cs2", "CS2", None, Compressed, "one track plan page"},
    {"fs", "fahrstrassen.cs2", "CS2", None, Compressed, "complete route configuration"},
    {"loksstat", "lokomotive.sr2", "CS2", None, Compressed, "current state of the locos"},
    {"magstat", "magnetartikel.sr2", "CS2", None, Compressed, "current state of the accessories"},
    {"gbsstat", "gleisbild.sr2", "CS2", None, Compressed, "current state of a track plan page"},
    {"fsstat", "fahrstrassen.sr2", "CS2", None, Compressed, "reserved for routes (not implemented)"},
    // Field notes: the spelling some programs use, and the MS2's own loco list; document 7.2: a free
    // text shown at a feedback block.
    {"lokstat", "lokomotive.sr2", "CS2", None, Compressed, "current state of the locos"},
    {"lokliste", "lokliste.cs2", "MS2", None, Ms2Text, "loco list of an MS2"},
    {"blokinfo", "blokinfo.cs2", "CS2", None, Ms2Text, "free text shown at a feedback block"},
}};

bool isPageKey(std::string_view key) {
    constexpr std::string_view prefix = "gbs-";
    if (key.size() <= prefix.size() || key.substr(0, prefix.size()) != prefix)
        return false;
    const auto number = key.substr(prefix.size());
    return std::all_of(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; });
}

} // namespace

std::uint8_t ConfigFileKey::followUpFrames() const {
    switch (followUp) {
    case LocoName:
        return 2;
    case Range:
        return 1;
    case None:
        break;
    }
    return 0;
}

std::span<const ConfigFileKey> configFileKeys() {
    return Keys;
}

std::optional<ConfigFileKey> findConfigFileKey(std::string_view key) {
    const std::string_view lookup = isPageKey(key) ? PageKey : key;
    const auto it =
        std::find_if(Keys.begin(), Keys.end(), [&](const auto& row) { return row.key == lookup; });
    if (it == Keys.end() || (lookup == PageKey && key == PageKey))
        return std::nullopt;
    return *it;
}

std::string fileNameForKey(std::string_view key) {
    const auto row = findConfigFileKey(key);
    if (!row)
        return {};
    return row->key == PageKey ? std::string(key) + ".cs2" : std::string(row->fileName);
}

} // namespace stellwerk::cs2config
