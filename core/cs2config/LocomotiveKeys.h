#pragma once

#include <string_view>

// The German keys of lokomotive.cs2, lokomotive.sr2 and the MS2 loco streams, in one place.
namespace stellwerk::cs2config::locokey {

// Sections and records.
inline constexpr std::string_view section = "lokomotive";
inline constexpr std::string_view stateSection = "lokstatus";
inline constexpr std::string_view locomotive = "lokomotive";
inline constexpr std::string_view lok = "lok"; // MS2 streams
inline constexpr std::string_view version = "version";
inline constexpr std::string_view session = "session";
inline constexpr std::string_view numloks = "numloks";

// Record values.
inline constexpr std::string_view major = "major";
inline constexpr std::string_view minor = "minor";
inline constexpr std::string_view id = "id";
inline constexpr std::string_view uid = "uid";
inline constexpr std::string_view name = "name";
inline constexpr std::string_view vorname = "vorname";
inline constexpr std::string_view adresse = "adresse";
inline constexpr std::string_view typ = "typ";
inline constexpr std::string_view dectyp = "dectyp"; // CS3-native files
inline constexpr std::string_view sid = "sid";
inline constexpr std::string_view mfxuid = "mfxuid";
inline constexpr std::string_view icon = "icon";
inline constexpr std::string_view symbol = "symbol";
inline constexpr std::string_view av = "av";
inline constexpr std::string_view bv = "bv";
inline constexpr std::string_view volume = "volume";
inline constexpr std::string_view progmask = "progmask";
inline constexpr std::string_view velocity = "velocity";
inline constexpr std::string_view richtung = "richtung";
inline constexpr std::string_view tachomax = "tachomax";
inline constexpr std::string_view vmax = "vmax";
inline constexpr std::string_view vmin = "vmin";
inline constexpr std::string_view xprot = "xprot";
inline constexpr std::string_view xprotokoll = "xprotokoll"; // older files
inline constexpr std::string_view mfxtyp = "mfxtyp";
inline constexpr std::string_view inTraktion = "inTraktion";
inline constexpr std::string_view nr = "nr";
inline constexpr std::string_view wert = "wert";

// Blocks of a record and their keys.
inline constexpr std::string_view funktionen = "funktionen";
inline constexpr std::string_view funktionen2 = "funktionen_2"; // CS3: F16-F31
inline constexpr std::string_view fkt = "fkt";                  // MS2 lokinfo
inline constexpr std::string_view dauer = "dauer";
inline constexpr std::string_view vorwaerts = "vorwaerts";
inline constexpr std::string_view rueckwaerts = "rueckwaerts";
inline constexpr std::string_view traktion = "traktion";
inline constexpr std::string_view tractionLok = "lok";
inline constexpr std::string_view lokname = "lokname";
inline constexpr std::string_view prg = "prg";
inline constexpr std::string_view maske = "maske";
inline constexpr std::string_view mfxAdr = "mfxAdr";
inline constexpr std::string_view target = "target";
inline constexpr std::string_view addr = "addr";
inline constexpr std::string_view xcel = "xcel";
inline constexpr std::string_view speedtable = "speedtable";
inline constexpr std::string_view numfunc = "numfunc";
inline constexpr std::string_view func = "func";

// The MS2 loco database version stream (ldbver).
inline constexpr std::string_view ldbVersion = "version";
inline constexpr std::string_view monat = "monat";
inline constexpr std::string_view jahr = "jahr";
inline constexpr std::string_view anzahl = "anzahl";

} // namespace stellwerk::cs2config::locokey
