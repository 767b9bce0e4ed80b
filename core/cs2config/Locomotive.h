#pragma once

#include "cs2config/Node.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// The decoder a locomotive has, as `.typ` names it ("mm2_prg", "mfx", ...). `None` is an empty
// `.typ=`; `Unknown` is any other text, which Locomotive::decoderText keeps.
enum class LocomotiveDecoder : std::uint8_t { None, Mm2Prg, Mm2Dil8, MmPrg, Mmm2Lok, Dcc, Mfx, Sx1, Unknown };

// "mm2_prg" for Mm2Prg; empty for None and Unknown.
std::string_view decoderName(LocomotiveDecoder decoder);
LocomotiveDecoder decoderFromName(std::string_view name);

// `.richtung`: 0 forward, 1 backward. Real files also hold -1 / 4294967295 (not set), read as
// Unknown; Unknown is never written, so such a line stays as it was.
enum class TravelDirection : std::uint8_t { Forward, Backward, Unknown };

// How a function key acts, from `..dauer`: 0 latching, -1 momentary, more than 0 timed.
enum class FunctionTrigger : std::uint8_t { Latching, Momentary, Timed, Unknown };

// One function key (F0-F31) of a locomotive: which icon it shows, how it triggers, its state.
struct Function {
    int number = -1;  // ..nr (0 = F0); -1 when the block has no readable number
    int icon = 0;     // ..typ: the number of the icon file
    int duration = 0; // ..dauer as written: 0 latching, -1 momentary, > 0 timed
    int value = 0;    // ..wert: the current state
    Node source;      // the block as read (keeps ..vorwaerts/..rueckwaerts and unknown keys)

    FunctionTrigger trigger() const;
    // The time of a timed function as the station writes it (the document names no unit); 0 otherwise.
    int timedValue() const { return trigger() == FunctionTrigger::Timed ? duration : 0; }
    // Sets ..dauer from a trigger; `timed` is used for Timed only (at least 1).
    void setTrigger(FunctionTrigger trigger, int timed = 1);
};

// One row of the extended CV programming dialog (`.prg` block).
struct CvRow {
    int cv = 0;       // ..adresse: the CV number
    std::string name; // ..name
    int value = 0;    // ..wert
    int mask = 0;     // ..maske: bit mask
    Node source;
};

// Where an mfx decoder keeps its configuration (`.mfxAdr` block, lokinfo stream and CS3 files).
struct MfxAddress {
    int target = 0;
    int name = 0;
    int address = 0;      // ..addr
    int acceleration = 0; // ..xcel
    int speedTable = 0;   // ..speedtable
    int volume = 0;
    int functionCount = 0; // ..numfunc
    int functions = 0;     // ..func
    Node source;
};

// One locomotive of a multiple unit (`.traktion` block of the unit's own record).
struct TractionMember {
    std::uint32_t uid = 0; // ..lok
    std::string name;      // ..lokname
    Node source;
};

// One locomotive of lokomotive.cs2 (a `lokomotive` record) or of an MS2 lokinfo stream (`lok`).
// Fields missing in the file read as the defaults below and are not added when written unchanged.
struct Locomotive {
    static constexpr std::uint32_t noTraction = 0xffffffff;

    std::uint32_t uid = 0;                               // .uid
    std::string name;                                    // .name
    std::string previousName;                            // .vorname: the name before the last rename
    std::uint32_t address = 0;                           // .adresse
    LocomotiveDecoder decoder = LocomotiveDecoder::None; // .typ (.dectyp in CS3 files)
    std::string decoderText;                             // .typ as written when decoder is Unknown
    std::uint32_t sid = 0;                               // .sid: mfx session id
    std::uint32_t mfxUid = 0;                            // .mfxuid
    std::string icon;                                    // .icon: file name without extension, empty for none
    int symbol = 0;          // .symbol: MS1 symbol (0 electric, 1 diesel, 2 steam, 3 none)
    int acceleration = 0;    // .av
    int braking = 0;         // .bv
    int volume = 0;          // .volume
    int programmingMask = 0; // .progmask
    int velocity = 0;        // .velocity
    TravelDirection direction = TravelDirection::Forward; // .richtung
    int tachoMax = 0;                                     // .tachomax
    int vMax = 0;                                         // .vmax
    int vMin = 0;                                         // .vmin
    int extendedProtocol = 0;                             // .xprot (.xprotokoll in older files)
    int mfxType = 0;                                      // .mfxtyp
    std::uint32_t inTraction = noTraction;                // .inTraktion: uid of the unit this loco runs in
    std::vector<Function> functions;      // .funktionen, .funktionen_2 (CS3: F16-F31), .fkt (MS2)
    std::vector<TractionMember> traction; // .traktion
    std::vector<CvRow> cvRows;            // .prg
    std::optional<MfxAddress> mfxAddress; // .mfxAdr
    Node source; // the record as read; empty (Root) for a locomotive that is not in a file yet

    // A record without a name and with uid 0: the placeholder some stations write first.
    bool isEmpty() const { return name.empty() && uid == 0; }
    const Function* function(int number) const;
    Function* function(int number);
    // The decoder type as it is written to `.typ`.
    std::string decoderTypeText() const;
};

} // namespace stellwerk::cs2config
