// Where the trains start: --place LOC=CONTACT[:END] as stellwerk-sim reads it, the end a train faces (a or
// b as the track graph names them, b when not said), and trains on real layouts of the corpus and on an
// overview page beside its detail pages; the real stellwerk-sim prints each accident and counts them on its
// web server (GET /accidents).

#include "sim/TrainPlacement.h"

#include "SimProgram.h"
#include "TrainTestSupport.h"
#include "cs2config/Diagnostics.h"
#include "transport/NetworkFraming.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTcpServer>
#include <QTcpSocket>
#include <filesystem>
#include <gtest/gtest.h>

namespace stellwerk::sim {

inline void PrintTo(const TrainPlacement& placement, std::ostream* out) {
    *out << std::hex << "0x" << placement.locId << std::dec << "=" << placement.contact << ":"
         << trackgraph::endName(placement.towards);
}

namespace {

using namespace std::chrono_literals;
using trackgraph::End;
using trackgraph::test::DrawnPage;

constexpr std::uint32_t PlacedBr218 = 0x4001;

std::filesystem::path corpus(const std::string& relative) {
    return std::filesystem::path(STELLWERK_SHARED_DIR) / "corpus" / relative;
}

StationLayout corpusLayout(const std::string& relative) {
    cs2config::Diagnostics diagnostics(relative);
    return StationLayout::load(corpus(relative), diagnostics);
}

TEST(TrainPlacementText, LocomotiveContactAndEnd) {
    EXPECT_EQ(parsePlacement("mfx:5=12:a").value(), (TrainPlacement{0x4005, 12, End::A}));
    EXPECT_EQ(parsePlacement("dcc:3=7:b").value(), (TrainPlacement{0xC003, 7, End::B}));
    EXPECT_EQ(parsePlacement("mm2:72=1009").value(), (TrainPlacement{72, 1009, End::B})) << "b when not said";
    EXPECT_EQ(parsePlacement("0x4001=1:B").value(), (TrainPlacement{0x4001, 1, End::B}));
}

TEST(TrainPlacementText, WhatIsWrongIsSaid) {
    const std::pair<const char*, const char*> cases[] = {
        {"mfx:5", "'mfx:5' is not LOC=CONTACT[:END] (e.g. mfx:5=12:a)"},
        {"mfx:5=twelve", "the contact 'twelve' is not a contact number"},
        {"mfx:5=-1", "the contact '-1' is not a contact number"},
        {"mfx:5=12:c", "the end 'c' is not a or b"},
        {"lgb:5=12", "LOC 'lgb:5': unknown protocol 'lgb' (mfx, dcc, mm2, sx1, sx2)"},
        {"0x10000=1", "LOC '0x10000' is not mfx:N, dcc:N, mm2:N or a Loc-ID up to 0xFFFF"},
    };
    for (const auto& [text, error] : cases) {
        const auto parsed = parsePlacement(text);
        ASSERT_FALSE(parsed) << text;
        EXPECT_EQ(parsed.error(), error);
    }
}

// Gleis 1 runs from its end a at W1 (west) to its end b at W2 (east); its contact covers 360..540 mm.
TEST(TrainPlacement, TheTrainFacesTheEndNamedAndRunsThereForward) {
    test::TrainRig rig(StationLayout::demo());
    rig.place({*parsePlacement("mfx:1=1:a")});
    EXPECT_EQ(rig.at(PlacedBr218).towards, End::A);
    EXPECT_EQ(rig.at(PlacedBr218).frontMm, 360);
    rig.drive(PlacedBr218, 1000);
    rig.run(3s);
    EXPECT_EQ(rig.reached(), (std::vector<std::uint16_t>{1, 7})) << "on to Einfahrt West";
    test::TrainRig other(StationLayout::demo());
    other.place({*parsePlacement("mfx:1=1")});
    EXPECT_EQ(other.at(PlacedBr218).towards, End::B);
    EXPECT_EQ(other.at(PlacedBr218).frontMm, 540);
    other.drive(PlacedBr218, 1000);
    other.run(3s);
    EXPECT_EQ(other.reached(), (std::vector<std::uint16_t>{1, 8})) << "on to Ausfahrt Ost";
}

TEST(TrainPlacement, AContactNoBlockHoldsIsRefused) {
    test::TrainRig rig(StationLayout::demo());
    rig.place({{PlacedBr218, 99, End::B}});
    EXPECT_EQ(rig.movement->problems(),
              std::vector<std::string>{"mfx:1: no block of the track plan holds contact 99"});
    EXPECT_EQ(rig.movement->trainCount(), 0U);
    EXPECT_EQ(rig.movement->place({0x0018, 42, End::A}),
              std::optional<std::string>("mm2:24: no block of the track plan holds contact 42"));
}

// karben.cs2: three station tracks between crossovers, every way off the page. 602 (contact 102 of device
// 0x100) leaves westwards over turnout 22 (article 3) straight and 24 (article 2) round, off the page.
TEST(TrainPlacement, KarbensTrainRunsOffThePageWestOfItsTrack) {
    test::TrainRig rig(corpusLayout("GBert__railroad/can2udp/files/maerklin/config"));
    constexpr std::uint32_t Loco = 0x000b; // 111 043-6
    rig.setTurnout(2, 0);
    rig.place({{Loco, 102, End::A}});
    EXPECT_TRUE(rig.station.contact(0x100, 102));
    rig.drive(Loco, 1000);
    rig.run(5s);
    EXPECT_EQ(rig.contacts.events, (std::vector<test::ContactEvent>{{102, true}, {102, false}}));
    EXPECT_EQ(rig.accidents,
              std::vector<std::string>{"buffer stop: 111 043-6 ran off the open end of the track "
                                       "beyond block \"602\" (page 'karben', column 1, row 3)"});
}

// With 24 straight as magnetartikel.cs2 has it, the same way runs through 24 trailing, set against it.
TEST(TrainPlacement, KarbensTrainRunsThroughATurnoutSetAgainstIt) {
    test::TrainRig rig(corpusLayout("GBert__railroad/can2udp/files/maerklin/config"));
    constexpr std::uint32_t Loco = 0x000b;
    rig.place({{Loco, 102, End::A}});
    rig.drive(Loco, 1000);
    rig.run(5s);
    ASSERT_EQ(rig.accidents.size(), 1U);
    EXPECT_EQ(
        rig.accidents[0].rfind("turnout run through: 111 043-6 ran through turnout 2 set against it", 0), 0U)
        << rig.accidents[0];
}

// TrainControl's "5 - Test": block 1031 is one tile (180 mm) between an open end (a) and the three-way
// turnout 23 (b); the 200 mm train reaches back onto the turnout.
TEST(TrainPlacement, TrainControlsTestPageRunsOffItsOpenEnd) {
    test::TrainRig rig(corpusLayout("bob123456678__TrainControl/cs2_sample_layout/config"));
    rig.place({{PlacedBr218, 1031, End::A}});
    EXPECT_EQ(rig.at(PlacedBr218).blocks, std::vector<int>{1});
    EXPECT_EQ(rig.movement->trainCount(), 1U);
    rig.drive(PlacedBr218, 1000);
    rig.run(1s);
    EXPECT_EQ(rig.accidents,
              std::vector<std::string>{"buffer stop: mfx:1 ran off the open end of the track "
                                       "beyond block \"Block 1031\" (page '5 - Test', column 4, "
                                       "row 6)"});
    EXPECT_TRUE(rig.at(PlacedBr218).derailed);
}

// The track graph tests' overview case: the Strecke (contact 5) runs on over an arrow to the Bahnhof (contact
// 6, then a buffer stop), and an overview page draws both contacts again. The train runs across the arrow on
// the detail pages' track.
TEST(TrainPlacement, ATrainCrossesFromPageToPageBesideAnOverview) {
    DrawnPage strecke(0, "Strecke");
    strecke.bufferStop(0, 0, true).straight(1, 1, 0).contact(2, 0, 5, "Ost").straight(3, 3, 0);
    strecke.arrow(4, 0, 0, 1, "Bahnhof");
    DrawnPage bahnhof(1, "Bahnhof");
    bahnhof.arrow(0, 0, 2, 0, "Strecke").straight(1, 1, 0).contact(2, 0, 6, "Gleis").straight(3, 3, 0);
    bahnhof.bufferStop(4, 0, false);
    DrawnPage overview(2, "Übersicht");
    overview.bufferStop(0, 0, true)
        .contact(1, 0, 5)
        .straight(2, 3, 0)
        .contact(4, 0, 6)
        .bufferStop(5, 0, false);
    test::TrainRig rig(test::drawnLayout({strecke, bahnhof, overview}));
    ASSERT_EQ(rig.station.layout().trackPlan().pages.size(), 3U);
    rig.place({{PlacedBr218, 5, End::B}});
    ASSERT_EQ(rig.movement->graph().blocks().size(), 2U);
    rig.drive(PlacedBr218, 1000);
    rig.run(1500ms);
    EXPECT_EQ(rig.contacts.events, (std::vector<test::ContactEvent>{{5, true}, {5, false}, {6, true}}));
    EXPECT_EQ(rig.blockName(rig.at(PlacedBr218).block), "Gleis");
    rig.run(2s);
    EXPECT_EQ(rig.accidents,
              std::vector<std::string>{"buffer stop: mfx:1 ran into the buffer stop beyond block "
                                       "\"Gleis\" (page 'Bahnhof', column 4, row 0)"});
}

} // namespace
} // namespace stellwerk::sim
