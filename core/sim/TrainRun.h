#pragma once

#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <deque>
#include <optional>
#include <set>
#include <vector>

namespace stellwerk::sim {

// One stretch of track a train is on, in its direction of travel: a block, or the track between two blocks
// (the tiles passed, and what lies beyond the last of them with the turnouts as they stood).
struct RunSpan {
    int block = 0;                                // 0: track between blocks
    trackgraph::End towards = trackgraph::End::B; // a block: the end the train runs to
    std::vector<trackgraph::TrackStep> steps;     // between blocks: the tiles in the order passed
    std::optional<trackgraph::BlockEnd> from;     // between blocks: the block end it starts at, if known
    trackgraph::Lead beyond;                      // between blocks: what follows the last step (no path)
    int lengthMm = 0;

    bool isBlock() const { return block != 0; }
};

// Why a train's front cannot go on: the track ends (buffer stop, open end, turntable), a turnout is set
// against it or moving, or the track leads round a loop without any block. `tile` is where the front stands.
struct RunStop {
    trackgraph::LeadKind kind = trackgraph::LeadKind::OpenEnd;
    trackgraph::TileId tile = 0;
    std::optional<trackgraph::TileId> turnout;
    std::optional<std::int64_t> article;
    bool facing = false;
    int lastBlock = 0; // the block the train came from
};

// A train's length of track in a block (millimetres from end a), or on one leg of a tile between blocks
// (millimetres from the leg's `from` port; any part of a turnout or crossing counts as all of it).
struct RunExtent {
    int block = 0;
    trackgraph::TileId tile = 0;
    std::uint8_t leg = 0;
    bool junction = false;
    double fromMm = 0;
    double toMm = 0;
};

// A turnout under a train: the leg it stands on must stay set while the train is on it.
struct TurnoutUnder {
    trackgraph::TileId tile = 0;
    std::uint8_t leg = 0;
};

// Where one train is on the track graph and how it moves on: the spans its length covers, front first, and
// how far its front is into the first. It follows the track with the turnouts as they stand when its front
// gets there (a facing turnout chooses the way, a trailing one set against it stops it).
class TrainRun {
public:
    // In the block holding `contact`, running towards `towards`, covering the contact (see TrainPlacement);
    // the rear reaches back over the track behind as the turnouts lie.
    static TrainRun placed(const trackgraph::TrackGraph& graph, const trackgraph::ContactOnBlock& contact,
                           int block, trackgraph::End towards, int lengthMm,
                           const trackgraph::PositionOf& positionOf);

    // Moves the front on by `distanceMm`; a RunStop when the track does not go on (the front then stands
    // where it ends).
    std::optional<RunStop> advance(double distanceMm, const trackgraph::TrackGraph& graph,
                                   const trackgraph::PositionOf& positionOf);
    // The rear becomes the front.
    void turnAround(const trackgraph::TrackGraph& graph);

    std::set<trackgraph::ContactKey> contactsCovered(const trackgraph::TrackGraph& graph) const;
    std::vector<RunExtent> extents(const trackgraph::TrackGraph& graph) const;
    std::vector<TurnoutUnder> turnoutsUnder(const trackgraph::TrackGraph& graph) const;

    const std::deque<RunSpan>& spans() const { return spans_; }
    double frontMm() const { return frontMm_; }
    int lengthMm() const { return lengthMm_; }
    // The block the front is in or last left.
    int lastBlock() const { return lastBlock_; }

private:
    TrainRun(RunSpan front, double frontMm, int lengthMm);

    std::optional<RunStop> enterNext(const trackgraph::TrackGraph& graph,
                                     const trackgraph::PositionOf& positionOf);
    std::optional<RunStop> enterBeyond(const trackgraph::Lead& beyond, const trackgraph::TrackGraph& graph);
    RunStop stopHere(const trackgraph::Lead& lead, const trackgraph::TrackGraph& graph) const;
    void replanAhead(const trackgraph::TrackGraph& graph, const trackgraph::PositionOf& positionOf);
    void dropUnentered();
    void extendBehind(const trackgraph::TrackGraph& graph, const trackgraph::PositionOf& positionOf);
    void releaseTail();
    // How far the body reaches into each span (travel coordinates), parallel to spans_.
    std::vector<std::pair<double, double>> coverage() const;
    double coveredMm() const;
    static void onSteps(const trackgraph::TrackGraph& graph, const RunSpan& span,
                        std::pair<double, double> covered, std::vector<RunExtent>& extents);

    std::deque<RunSpan> spans_;
    double frontMm_ = 0;
    int lengthMm_ = 0;
    int lastBlock_ = 0;
};

// The spans a train runs on, as TrainRun makes them.
RunSpan blockSpan(const trackgraph::TrackGraph& graph, int block, trackgraph::End towards);
RunSpan stepsSpan(std::vector<trackgraph::TrackStep> steps, std::optional<trackgraph::BlockEnd> from,
                  trackgraph::Lead beyond);
// The same span run the other way.
RunSpan reversed(const RunSpan& span, const trackgraph::TrackGraph& graph);

} // namespace stellwerk::sim
