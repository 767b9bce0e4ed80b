// The track of every tile type of the CS2 in every rotation: where it leaves the tile, which legs a
// turnout's positions set, and how long each piece is. tests/ui/trackplan/TrackGraphDrawingTest.cpp checks
// the same table against the plan's drawings.
#include "trackgraph/TileShape.h"

#include "cs2config/TrackElementType.h"

#include <gtest/gtest.h>
#include <map>
#include <set>
#include <string>

using namespace stellwerk::trackgraph;

namespace {

using P = Port;

// Where each type's track leaves the tile unrotated (.drehung=0), written out from the plan's drawings.
const std::map<std::string, std::set<Port>> unrotatedExits{
    {"gerade", {P::West, P::East}},
    {"kreuzung", {P::West, P::East, P::North, P::South}},
    {"unterfuehrung", {P::West, P::East, P::North, P::South}},
    {"prellbock", {P::West}},
    {"bogen", {P::East, P::South}},
    {"doppelbogen", {P::East, P::South, P::West, P::North}},
    {"tunnel", {P::West, P::East}},
    {"linksweiche", {P::South, P::West, P::North}},
    {"rechtsweiche", {P::South, P::East, P::North}},
    {"dreiwegweiche", {P::South, P::West, P::North, P::East}},
    {"yweiche", {P::South, P::West, P::East}},
    {"dkweiche", {P::South, P::West, P::North, P::East}},
    {"dkweiche_2", {P::South, P::West, P::North, P::East}},
    {"s88kontakt", {P::West, P::East}},
    {"s88bogen", {P::East, P::South}},
    {"s88doppelbogen", {P::East, P::South, P::West, P::North}},
    {"pfeil", {P::West}},
    {"entkuppler", {P::West, P::East}},
    {"entkuppler_1", {P::West, P::East}},
    {"bahnschranke", {P::West, P::East}},
    {"hosentraeger", {P::NorthWest, P::SouthEast, P::SouthWest, P::NorthEast, P::West, P::East}},
    {"dkw3_li", {P::South, P::West, P::North, P::East}},
    {"dkw3_li_2", {P::South, P::West, P::North, P::East}},
    {"dkw3_re", {P::South, P::East, P::North, P::West}},
    {"dkw3_re_2", {P::South, P::East, P::North, P::West}},
};

std::set<Port> exitsOf(const TileShape& shape) {
    std::set<Port> exits;
    for (const Leg& leg : shape.legs())
        for (const Port port : {leg.from, leg.to})
            if (isGeometric(port))
                exits.insert(port);
    return exits;
}

std::set<Port> expectedExits(const std::string& type, int rotation) {
    std::set<Port> exits;
    if (type.starts_with("signal"))
        exits = {P::West, P::East};
    else if (type.starts_with("drehscheibe") || type.starts_with("schiebebuehne"))
        exits = {P::West};
    else if (const auto found = unrotatedExits.find(type); found != unrotatedExits.end())
        exits = found->second;
    std::set<Port> turned;
    for (const Port port : exits)
        turned.insert(rotated(port, rotation));
    return turned;
}

// The legs a position sets, as pairs of ports.
std::set<std::set<Port>> legsSetIn(const std::string& type, int position) {
    std::set<std::set<Port>> legs;
    for (const Leg& leg : tileShapeOf(type).legs())
        if (leg.setIn(position))
            legs.insert({leg.from, leg.to});
    return legs;
}

} // namespace

TEST(TileShape, AQuarterTurnTurnsCounterClockwiseAsThePlanDrawsIt) {
    EXPECT_EQ(rotated(P::West, 1), P::South);
    EXPECT_EQ(rotated(P::East, 1), P::North);
    EXPECT_EQ(rotated(P::North, 1), P::West);
    EXPECT_EQ(rotated(P::South, 3), P::West);
    EXPECT_EQ(rotated(P::NorthWest, 1), P::SouthWest);
    EXPECT_EQ(rotated(P::West, 2), P::East);
    EXPECT_EQ(rotated(P::Link, 3), P::Link);
    EXPECT_EQ(facing(P::NorthEast), P::SouthWest);
    EXPECT_EQ(facing(P::West), P::East);
}

TEST(TileShape, EveryTypeOfTheStationLeavesTheTileWhereItsTrackIsDrawnInEveryRotation) {
    for (const stellwerk::cs2config::TrackElementType& type : stellwerk::cs2config::trackElementTypes())
        for (int rotation = 0; rotation < 4; ++rotation) {
            const std::string name(type.name);
            EXPECT_EQ(exitsOf(rotatedShape(tileShapeOf(name), rotation)), expectedExits(name, rotation))
                << name << " rotation " << rotation;
        }
}

TEST(TileShape, AKarbenTurnoutLiesAlongItsTrackWhenTurned) {
    // karben.cs2: rechtsweiche .drehung=3 at column 5, row 1 has its points west, the straight leg east
    // and the diverging leg south, down to the turnout below it.
    const TileShape turned = rotatedShape(tileShapeOf("rechtsweiche"), 3);
    EXPECT_EQ(exitsOf(turned), (std::set<Port>{P::West, P::East, P::South}));
    EXPECT_EQ(turned.legs()[0].from, P::West);
    EXPECT_EQ(turned.legs()[0].to, P::South);
    EXPECT_TRUE(turned.legs()[0].setIn(0));
    EXPECT_EQ(turned.legs()[1].to, P::East);
    EXPECT_TRUE(turned.legs()[1].setIn(1));
}

TEST(TileShape, WhatEachTypeIsForTheGraph) {
    EXPECT_EQ(tileShapeOf("gerade").role, TileRole::Track);
    EXPECT_EQ(tileShapeOf("unterfuehrung").role, TileRole::Track); // the tracks do not meet
    EXPECT_EQ(tileShapeOf("doppelbogen").role, TileRole::Track);
    EXPECT_EQ(tileShapeOf("kreuzung").role, TileRole::Crossing);
    EXPECT_EQ(tileShapeOf("prellbock").role, TileRole::BufferStop);
    EXPECT_EQ(tileShapeOf("s88bogen").role, TileRole::Contact);
    EXPECT_EQ(tileShapeOf("signal_f_hp012").role, TileRole::Signal);
    EXPECT_EQ(tileShapeOf("signal_sh01").role, TileRole::Signal);
    EXPECT_EQ(tileShapeOf("entkuppler_1").role, TileRole::Track);
    EXPECT_EQ(tileShapeOf("bahnschranke").role, TileRole::Track);
    EXPECT_EQ(tileShapeOf("pfeil").role, TileRole::PageLink);
    EXPECT_EQ(tileShapeOf("drehscheibe_dig_3").role, TileRole::Turntable);
    EXPECT_EQ(tileShapeOf("dkweiche_2").role, TileRole::Turnout);
    for (const char* notTrack : {"std_rot_gruen_0", "k84_einfach", "lampe_gn", "fahrstrasse", "text", "leer",
                                 "custom_perm_left", ""}) {
        EXPECT_EQ(tileShapeOf(notTrack).role, TileRole::None) << notTrack;
        EXPECT_FALSE(tileShapeOf(notTrack).isTrack()) << notTrack;
    }
    EXPECT_TRUE(tileShapeOf("kreuzung").isJunction());
    EXPECT_FALSE(tileShapeOf("unterfuehrung").isJunction());
}

TEST(TileShape, TurnoutPositionsAreTheKeyboardsNumbers) {
    using Legs = std::set<std::set<Port>>;
    // Two-way turnouts: 0 diverging (red, round), 1 straight (green).
    EXPECT_EQ(legsSetIn("linksweiche", 0), (Legs{{P::South, P::West}}));
    EXPECT_EQ(legsSetIn("linksweiche", 1), (Legs{{P::South, P::North}}));
    EXPECT_EQ(legsSetIn("rechtsweiche", 0), (Legs{{P::South, P::East}}));
    EXPECT_EQ(legsSetIn("rechtsweiche", 1), (Legs{{P::South, P::North}}));
    // Y: 0 left, 1 right.
    EXPECT_EQ(legsSetIn("yweiche", 0), (Legs{{P::South, P::West}}));
    EXPECT_EQ(legsSetIn("yweiche", 1), (Legs{{P::South, P::East}}));
    // Three-way: 0 left, 1 straight, 2 right.
    EXPECT_EQ(legsSetIn("dreiwegweiche", 0), (Legs{{P::South, P::West}}));
    EXPECT_EQ(legsSetIn("dreiwegweiche", 1), (Legs{{P::South, P::North}}));
    EXPECT_EQ(legsSetIn("dreiwegweiche", 2), (Legs{{P::South, P::East}}));
    // Double slip, one drive: 0 both curves, 1 both straights.
    EXPECT_EQ(legsSetIn("dkweiche", 0), (Legs{{P::South, P::West}, {P::North, P::East}}));
    EXPECT_EQ(legsSetIn("dkweiche", 1), (Legs{{P::South, P::North}, {P::West, P::East}}));
    // Two drives: the keyboard's four positions (ui/keyboard AccessoryIcon, ui/trackplan TurnoutShapes).
    EXPECT_EQ(legsSetIn("dkweiche_2", 0), (Legs{{P::South, P::West}, {P::North, P::East}}));
    EXPECT_EQ(legsSetIn("dkweiche_2", 1), (Legs{{P::South, P::North}, {P::West, P::East}}));
    EXPECT_EQ(legsSetIn("dkweiche_2", 2), (Legs{{P::South, P::West}, {P::West, P::East}}));
    EXPECT_EQ(legsSetIn("dkweiche_2", 3), (Legs{{P::North, P::East}, {P::South, P::North}}));
    EXPECT_EQ(legsSetIn("hosentraeger", 0),
              (Legs{{P::NorthWest, P::SouthEast}, {P::SouthWest, P::NorthEast}}));
    EXPECT_EQ(legsSetIn("hosentraeger", 1), (Legs{{P::West, P::East}}));
    // Plain track is always there.
    EXPECT_EQ(legsSetIn("kreuzung", 3), (Legs{{P::West, P::East}, {P::North, P::South}}));
}

TEST(TileShape, AConnectionAsksForTheLowestPositionThatSetsItsLeg) {
    for (const Leg& leg : tileShapeOf("dkweiche_2").legs()) {
        const bool straight = leg.lengthMm() == StraightTileMm;
        EXPECT_EQ(leg.position(), straight ? 1 : 0);
    }
    EXPECT_EQ(tileShapeOf("dreiwegweiche").legs()[2].position(), 2);
}

TEST(TileShape, PositionNamesFollowTheKeyboard) {
    EXPECT_EQ(positionName(TurnoutKind::TwoWay, 0), "diverging");
    EXPECT_EQ(positionName(TurnoutKind::TwoWay, 1), "straight");
    EXPECT_EQ(positionName(TurnoutKind::Y, 0), "left");
    EXPECT_EQ(positionName(TurnoutKind::Y, 1), "right");
    EXPECT_EQ(positionName(TurnoutKind::ThreeWay, 0), "left");
    EXPECT_EQ(positionName(TurnoutKind::ThreeWay, 1), "straight");
    EXPECT_EQ(positionName(TurnoutKind::ThreeWay, 2), "right");
    EXPECT_EQ(positionName(TurnoutKind::DoubleSlip, 0), "diverging");
    EXPECT_EQ(positionName(TurnoutKind::DoubleSlipTwoDrives, 1), "straight");
    EXPECT_EQ(positionName(TurnoutKind::DoubleSlipTwoDrives, 2), "straight-diverging");
}

TEST(TileShape, TileLengthsAreTheDocumentedOnes) {
    EXPECT_EQ((Leg{P::West, P::East}.lengthMm()), 180);
    EXPECT_EQ((Leg{P::East, P::South}.lengthMm()), 141);
    EXPECT_EQ((Leg{P::NorthWest, P::SouthEast}.lengthMm()), 255);
    EXPECT_EQ((Leg{P::West, P::End}.lengthMm()), 90);
    EXPECT_EQ((Leg{P::West, P::Link}.lengthMm()), 90);
}

TEST(TileShape, SignalsFaceTrainsComingFromTheirWestSideUnrotated) {
    EXPECT_EQ(rotatedShape(tileShapeOf("signal"), 0).signalApproach, P::West);
    EXPECT_EQ(rotatedShape(tileShapeOf("signal_p_hp012s"), 2).signalApproach, P::East);
    EXPECT_EQ(rotatedShape(tileShapeOf("signal"), 1).signalApproach, P::South);
}
