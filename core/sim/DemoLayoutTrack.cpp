// The demo layout's track for the train movement; it matches resources/demo-layout/config/gleisbilder:
// on the Bahnhof page W1 (points west) leads round into Gleis 2, W2 (points east) joins both tracks, W3
// leads round into the Abstellgleis, which runs on to the Bw page; the Bw's tracks have no contacts, so
// for the trains the Abstellgleis ends at its contact. The Strecke page carries Block 1-4 as a loop.

#include "sim/TrainTrack.h"

namespace stellwerk::sim {

namespace {

// Loc-ID of MM accessory keyboard number `id` (field notes: 0x3000 = keyboard 1).
constexpr std::uint32_t mmAccessory(std::uint32_t id) {
    return 0x3000 + id - 1;
}

constexpr std::uint32_t W1 = mmAccessory(1); // Einfahrt West: round leads into Gleis 2
constexpr std::uint32_t W2 = mmAccessory(2); // Ausfahrt Ost, faced by trains running "behind"
constexpr std::uint32_t W3 = mmAccessory(3); // Abstellgleis
constexpr std::uint8_t Round = 0;

enum Section { EinfahrtWest, Gleis1, Gleis2, AusfahrtOst, Block1, Block2, Block3, Block4, Abstellgleis };

SectionExit to(int next) {
    return {next, 0, 0, SectionExit::BufferStop};
}

SectionExit facing(std::uint32_t turnout, int straight, int diverging) {
    return {straight, turnout, Round, diverging};
}

FeedbackSection section(const char* name, std::uint16_t contact, int lengthMm, SectionExit ahead,
                        SectionExit behind) {
    return {name, 0x0000, contact, lengthMm, ahead, behind};
}

} // namespace

TrainTrack TrainTrack::demo() {
    TrainTrack track;
    track.sections = {
        section("Einfahrt West", 7, 1200, facing(W1, Gleis1, Gleis2), to(Block4)),
        section("Gleis 1", 1, 2000, to(AusfahrtOst), to(EinfahrtWest)),
        section("Gleis 2", 2, 2000, to(AusfahrtOst), to(EinfahrtWest)),
        section("Ausfahrt Ost", 8, 1200, facing(W3, Block1, Abstellgleis), facing(W2, Gleis1, Gleis2)),
        section("Block 1", 3, 2500, to(Block2), to(AusfahrtOst)),
        section("Block 2", 4, 2500, to(Block3), to(Block1)),
        section("Block 3", 5, 2500, to(Block4), to(Block2)),
        section("Block 4", 6, 2500, to(EinfahrtWest), to(Block3)),
        section("Abstellgleis", 9, 1000, to(SectionExit::BufferStop), to(AusfahrtOst)),
    };
    // lokomotive.cs2: BR 218 Ost (mfx 0x4001), ICE 3 Velaro (mfx 0x4002), V 100 2023 (MM2 0x18),
    // Köf III (MM2 0x02).
    track.placements = {
        {0x4001, Gleis1, 1500},
        {0x4002, Block2, 1800},
        {0x0018, Gleis2, 1200},
        {0x0002, Abstellgleis, 600},
    };
    return track;
}

} // namespace stellwerk::sim
