// The track of every tile type, written unrotated as ui/trackplan draws it (TrackShapes.cpp,
// TurnoutShapes.cpp, SignalShapes.cpp, FeatureShapes.cpp): plain track runs west to east, a turnout's
// points are at the south side with its straight leg to the north, signals and contacts lie on a west-east
// track. tests/ui/trackplan/TrackGraphDrawingTest.cpp checks this table against the drawings.
#include "trackgraph/TileShape.h"

#include <bit>
#include <initializer_list>

namespace stellwerk::trackgraph {

namespace {

using P = Port;

constexpr std::uint8_t bits(std::initializer_list<int> positions) {
    std::uint8_t mask = 0;
    for (const int position : positions)
        mask = std::uint8_t(mask | (1U << position));
    return mask;
}

TileShape shape(TileRole role, std::initializer_list<Leg> legs, TurnoutKind turnout = TurnoutKind::None) {
    TileShape result;
    result.role = role;
    result.turnout = turnout;
    for (const Leg& leg : legs)
        result.legArray[result.legCount++] = leg;
    return result;
}

// One `.typ` word, or a prefix of words when it ends in '*'; the first match wins.
struct ShapeEntry {
    std::string_view type;
    TileShape shape;
};

const std::span<const ShapeEntry> shapeTable() {
    using R = TileRole;
    using K = TurnoutKind;
    const Leg westEast{P::West, P::East};
    static const ShapeEntry table[] = {
        {"gerade", shape(R::Track, {westEast})},
        {"bogen", shape(R::Track, {{P::East, P::South}})},
        {"doppelbogen", shape(R::Track, {{P::East, P::South}, {P::West, P::North}})},
        {"kreuzung", shape(R::Crossing, {westEast, {P::North, P::South}})},
        {"unterfuehrung", shape(R::Track, {westEast, {P::North, P::South}})},
        {"prellbock", shape(R::BufferStop, {{P::West, P::End}})},
        {"tunnel", shape(R::Track, {westEast})},
        {"linksweiche",
         shape(R::Turnout, {{P::South, P::West, bits({0})}, {P::South, P::North, bits({1})}}, K::TwoWay)},
        {"rechtsweiche",
         shape(R::Turnout, {{P::South, P::East, bits({0})}, {P::South, P::North, bits({1})}}, K::TwoWay)},
        {"yweiche",
         shape(R::Turnout, {{P::South, P::West, bits({0})}, {P::South, P::East, bits({1})}}, K::Y)},
        {"dreiwegweiche", shape(R::Turnout,
                                {{P::South, P::West, bits({0})},
                                 {P::South, P::North, bits({1})},
                                 {P::South, P::East, bits({2})}},
                                K::ThreeWay)},
        {"dkweiche_2", shape(R::Turnout,
                             {{P::South, P::West, bits({0, 2})},
                              {P::North, P::East, bits({0, 3})},
                              {P::South, P::North, bits({1, 3})},
                              {P::West, P::East, bits({1, 2})}},
                             K::DoubleSlipTwoDrives)},
        {"dkweiche", shape(R::Turnout,
                           {{P::South, P::West, bits({0})},
                            {P::North, P::East, bits({0})},
                            {P::South, P::North, bits({1})},
                            {P::West, P::East, bits({1})}},
                           K::DoubleSlip)},
        {"dkw3_li*",
         shape(
             R::Turnout,
             {{P::South, P::West, bits({0})}, {P::South, P::North, bits({1})}, {P::West, P::East, bits({2})}},
             K::ThreeWaySlip)},
        {"dkw3_re*",
         shape(
             R::Turnout,
             {{P::South, P::East, bits({0})}, {P::South, P::North, bits({1})}, {P::West, P::East, bits({2})}},
             K::ThreeWaySlip)},
        {"hosentraeger", shape(R::Turnout,
                               {{P::NorthWest, P::SouthEast, bits({0})},
                                {P::SouthWest, P::NorthEast, bits({0})},
                                {P::West, P::East, bits({1})}},
                               K::Scissors)},
        {"signal*", shape(R::Signal, {westEast})},
        {"s88kontakt", shape(R::Contact, {westEast})},
        {"s88bogen", shape(R::Contact, {{P::East, P::South}})},
        {"s88doppelbogen", shape(R::Contact, {{P::East, P::South}, {P::West, P::North}})},
        {"pfeil", shape(R::PageLink, {{P::West, P::Link}})},
        {"entkuppler*", shape(R::Track, {westEast})},
        {"bahnschranke", shape(R::Track, {westEast})},
        {"drehscheibe*", shape(R::Turntable, {{P::West, P::End}})},
        {"schiebebuehne_*", shape(R::Turntable, {{P::West, P::End}})},
    };
    return table;
}

bool matches(std::string_view pattern, std::string_view type) {
    if (pattern.ends_with('*'))
        return type.starts_with(pattern.substr(0, pattern.size() - 1));
    return pattern == type;
}

} // namespace

bool isGeometric(Port port) {
    return std::uint8_t(port) < GeometricPorts;
}

Port rotated(Port port, int quarterTurns) {
    if (!isGeometric(port))
        return port;
    const int turned = int(port) + GeometricPorts - 2 * (quarterTurns & 3);
    return Port(turned % GeometricPorts);
}

Port facing(Port port) {
    return isGeometric(port) ? Port((int(port) + 4) % GeometricPorts) : port;
}

std::array<int, 2> offsetOf(Port port) {
    constexpr std::array<std::array<int, 2>, GeometricPorts> offsets{
        {{0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}}};
    return isGeometric(port) ? offsets[std::size_t(port)] : std::array<int, 2>{0, 0};
}

std::string_view portName(Port port) {
    constexpr std::string_view names[] = {
        "north",      "north-east", "east",       "south-east",           "south",
        "south-west", "west",       "north-west", "link to another page", "end"};
    return names[std::size_t(port)];
}

bool Leg::setIn(int position) const {
    return always() || (position >= 0 && position < 8 && (positions >> position) & 1U);
}

int Leg::position() const {
    return always() ? 0 : std::countr_zero(unsigned(positions));
}

int Leg::lengthMm() const {
    if (!isGeometric(from) || !isGeometric(to))
        return HalfTileMm;
    const int apart = (int(to) - int(from) + GeometricPorts) % GeometricPorts;
    if (apart == 4)
        return int(from) % 2 == 0 ? StraightTileMm : DiagonalTileMm;
    return CurveTileMm;
}

const TileShape& tileShapeOf(std::string_view type) {
    static const TileShape none;
    for (const ShapeEntry& entry : shapeTable())
        if (matches(entry.type, type))
            return entry.shape;
    return none;
}

TileShape rotatedShape(const TileShape& shape, int quarterTurns) {
    TileShape turned = shape;
    for (std::uint8_t i = 0; i < shape.legCount; ++i) {
        turned.legArray[i].from = rotated(shape.legArray[i].from, quarterTurns);
        turned.legArray[i].to = rotated(shape.legArray[i].to, quarterTurns);
    }
    turned.signalApproach = rotated(shape.signalApproach, quarterTurns);
    return turned;
}

int positionCount(TurnoutKind kind) {
    switch (kind) {
    case TurnoutKind::ThreeWay:
    case TurnoutKind::ThreeWaySlip:
        return 3;
    case TurnoutKind::DoubleSlipTwoDrives:
        return 4;
    case TurnoutKind::None:
    case TurnoutKind::TwoWay:
    case TurnoutKind::Y:
    case TurnoutKind::DoubleSlip:
    case TurnoutKind::Scissors:
        break;
    }
    return 2;
}

std::string_view positionName(TurnoutKind kind, int position) {
    switch (kind) {
    case TurnoutKind::Y:
        return position == 0 ? "left" : "right";
    case TurnoutKind::ThreeWay:
        return position == 0 ? "left" : position == 1 ? "straight" : "right";
    case TurnoutKind::DoubleSlipTwoDrives:
        if (position >= 2)
            return position == 2 ? "straight-diverging" : "diverging-straight";
        break;
    case TurnoutKind::ThreeWaySlip:
        if (position == 2)
            return "crossing";
        break;
    case TurnoutKind::None:
    case TurnoutKind::TwoWay:
    case TurnoutKind::DoubleSlip:
    case TurnoutKind::Scissors:
        break;
    }
    return position == 1 ? "straight" : "diverging";
}

} // namespace stellwerk::trackgraph
