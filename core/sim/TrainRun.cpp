#include "sim/TrainRun.h"

#include <algorithm>

namespace stellwerk::sim {

using trackgraph::BlockEnd;
using trackgraph::End;
using trackgraph::Lead;
using trackgraph::LeadKind;
using trackgraph::TrackGraph;
using trackgraph::TrackStep;

namespace {

constexpr int MostSpansBehind = 16; // a train longer than this many blocks and ways behind is cut short

int lengthOf(const std::vector<TrackStep>& steps) {
    int length = 0;
    for (const TrackStep& step : steps)
        length += step.lengthMm;
    return length;
}

TrackStep backwards(const TrackStep& step) {
    return {step.tile, step.leg, step.exit, step.entry, step.lengthMm};
}

// How many steps the front has entered: those that begin before it.
std::size_t stepsEntered(const std::vector<TrackStep>& steps, double frontMm) {
    double start = 0;
    std::size_t entered = 0;
    while (entered < steps.size() && start < frontMm)
        start += steps[entered++].lengthMm;
    return entered;
}

// A stretch [fromMm, toMm] of a span run towards `towards`, in the block's own millimetres from end a.
std::pair<double, double> inBlock(const RunSpan& span, double fromMm, double toMm) {
    if (span.towards == End::B)
        return {fromMm, toMm};
    return {span.lengthMm - toMm, span.lengthMm - fromMm};
}

} // namespace

RunSpan blockSpan(const TrackGraph& graph, int block, End towards) {
    RunSpan span;
    span.block = block;
    span.towards = towards;
    span.lengthMm = graph.block(block).lengthMm;
    return span;
}

RunSpan stepsSpan(std::vector<TrackStep> steps, std::optional<BlockEnd> from, Lead beyond) {
    RunSpan span;
    span.steps = std::move(steps);
    span.from = from;
    beyond.path.clear();
    span.beyond = std::move(beyond);
    span.lengthMm = lengthOf(span.steps);
    return span;
}

RunSpan reversed(const RunSpan& span, const TrackGraph& graph) {
    if (span.isBlock())
        return blockSpan(graph, span.block, otherEnd(span.towards));
    std::vector<TrackStep> steps;
    for (auto step = span.steps.rbegin(); step != span.steps.rend(); ++step)
        steps.push_back(backwards(*step));
    Lead beyond; // back to the block end it began at (an open end when that is not known)
    if (span.from) {
        beyond.kind = LeadKind::Block;
        beyond.reached = *span.from;
    }
    std::optional<BlockEnd> from;
    if (span.beyond.kind == LeadKind::Block)
        from = span.beyond.reached;
    return stepsSpan(std::move(steps), from, std::move(beyond));
}

TrainRun::TrainRun(RunSpan front, double frontMm, int lengthMm)
    : frontMm_(frontMm), lengthMm_(lengthMm), lastBlock_(front.block) {
    spans_.push_back(std::move(front));
}

TrainRun TrainRun::placed(const TrackGraph& graph, const trackgraph::ContactOnBlock& contact, int block,
                          End towards, int lengthMm, const trackgraph::PositionOf& positionOf) {
    const int blockMm = graph.block(block).lengthMm;
    const double farEdge = towards == End::B ? contact.toMm : blockMm - contact.fromMm;
    const double front = std::clamp(farEdge, double(std::min(lengthMm, blockMm)), double(blockMm));
    TrainRun run(blockSpan(graph, block, towards), front, lengthMm);
    run.extendBehind(graph, positionOf); // a block shorter than the train
    return run;
}

// The rear reaches back out of its block over the track behind, with the turnouts as they lie.
void TrainRun::extendBehind(const TrackGraph& graph, const trackgraph::PositionOf& positionOf) {
    for (int spans = 0; spans < MostSpansBehind && coveredMm() < lengthMm_; ++spans) {
        if (!spans_.back().isBlock())
            return;
        const BlockEnd leaving{spans_.back().block, otherEnd(spans_.back().towards)};
        Lead lead = graph.follow(leaving, positionOf);
        const Lead beyond{lead.kind, lead.reached, {}, lead.turnout, lead.article, lead.facing};
        if (!lead.path.empty())
            spans_.push_back(reversed(stepsSpan(std::move(lead.path), leaving, beyond), graph));
        if (beyond.kind != LeadKind::Block)
            return;
        spans_.push_back(blockSpan(graph, beyond.reached.block, beyond.reached.end));
    }
}

std::optional<RunStop> TrainRun::advance(double distanceMm, const TrackGraph& graph,
                                         const trackgraph::PositionOf& positionOf) {
    replanAhead(graph, positionOf);
    frontMm_ += distanceMm;
    std::optional<RunStop> stop;
    while (!stop && frontMm_ > spans_.front().lengthMm)
        stop = enterNext(graph, positionOf);
    if (stop)
        frontMm_ = spans_.front().lengthMm; // it stands where the track ends
    releaseTail();
    return stop;
}

std::optional<RunStop> TrainRun::enterNext(const TrackGraph& graph,
                                           const trackgraph::PositionOf& positionOf) {
    if (!spans_.front().isBlock())
        return enterBeyond(Lead(spans_.front().beyond), graph);
    const BlockEnd leaving{spans_.front().block, spans_.front().towards};
    Lead lead = graph.follow(leaving, positionOf);
    if (lead.path.empty())
        return enterBeyond(lead, graph);
    frontMm_ -= spans_.front().lengthMm;
    std::vector<TrackStep> steps = std::move(lead.path);
    spans_.push_front(stepsSpan(std::move(steps), leaving, std::move(lead)));
    return std::nullopt;
}

std::optional<RunStop> TrainRun::enterBeyond(const Lead& beyond, const TrackGraph& graph) {
    if (beyond.kind != LeadKind::Block)
        return stopHere(beyond, graph);
    frontMm_ -= spans_.front().lengthMm;
    lastBlock_ = beyond.reached.block;
    spans_.push_front(blockSpan(graph, beyond.reached.block, otherEnd(beyond.reached.end)));
    return std::nullopt;
}

RunStop TrainRun::stopHere(const Lead& lead, const TrackGraph& graph) const {
    const RunSpan& front = spans_.front();
    const trackgraph::TileId tile =
        front.isBlock() ? graph.block(front.block).end(front.towards).tile : front.steps.back().tile;
    return {lead.kind, tile, lead.turnout, lead.article, lead.facing, lastBlock_};
}

// The way ahead of the front, from the last tile it entered, with the turnouts as they stand now: a facing
// turnout switched since takes it elsewhere, one that moves or is set against it stops the way there.
void TrainRun::replanAhead(const TrackGraph& graph, const trackgraph::PositionOf& positionOf) {
    RunSpan& front = spans_.front();
    if (front.isBlock())
        return;
    const std::size_t entered = stepsEntered(front.steps, frontMm_);
    if (entered == 0)
        return; // the front is on the first tile as soon as it leaves its block
    Lead lead = graph.followFrom(front.steps[entered - 1].tile, front.steps[entered - 1].exit, positionOf);
    front.steps.resize(entered);
    front.steps.insert(front.steps.end(), lead.path.begin(), lead.path.end());
    lead.path.clear();
    front.beyond = std::move(lead);
    front.lengthMm = lengthOf(front.steps);
}

void TrainRun::dropUnentered() {
    RunSpan& front = spans_.front();
    if (front.isBlock())
        return;
    front.steps.resize(std::max<std::size_t>(1, stepsEntered(front.steps, frontMm_)));
    front.beyond = Lead{};
    front.lengthMm = lengthOf(front.steps);
}

void TrainRun::turnAround(const TrackGraph& graph) {
    dropUnentered();
    releaseTail();
    const double rearStart = coverage().back().first;
    std::deque<RunSpan> turned;
    for (const RunSpan& span : spans_)
        turned.push_front(reversed(span, graph));
    spans_ = std::move(turned);
    frontMm_ = spans_.front().lengthMm - rearStart;
    for (const RunSpan& span : spans_)
        if (span.isBlock()) {
            lastBlock_ = span.block; // the first block its new front comes from or is in
            break;
        }
}

std::vector<std::pair<double, double>> TrainRun::coverage() const {
    std::vector<std::pair<double, double>> covered;
    double remaining = lengthMm_;
    for (std::size_t i = 0; i < spans_.size(); ++i) {
        const double end = i == 0 ? frontMm_ : spans_[i].lengthMm;
        const double start = std::clamp(end - remaining, 0.0, end);
        covered.emplace_back(start, end);
        remaining -= end - start;
    }
    return covered;
}

double TrainRun::coveredMm() const {
    double covered = frontMm_;
    for (std::size_t i = 1; i < spans_.size(); ++i)
        covered += spans_[i].lengthMm;
    return std::min(covered, double(lengthMm_));
}

// Forgets the spans the rear has left, as a contact frees once the last axle is off it.
void TrainRun::releaseTail() {
    const std::vector<std::pair<double, double>> covered = coverage();
    std::size_t keep = spans_.size();
    while (keep > 1 && covered[keep - 1].first >= covered[keep - 1].second)
        --keep;
    spans_.resize(keep);
}

std::set<trackgraph::ContactKey> TrainRun::contactsCovered(const TrackGraph& graph) const {
    std::set<trackgraph::ContactKey> contacts;
    const std::vector<std::pair<double, double>> covered = coverage();
    for (std::size_t i = 0; i < spans_.size(); ++i) {
        if (!spans_[i].isBlock() || covered[i].first >= covered[i].second)
            continue;
        const auto [low, high] = inBlock(spans_[i], covered[i].first, covered[i].second);
        for (const trackgraph::ContactOnBlock& contact : graph.block(spans_[i].block).contacts)
            if (contact.fromMm < high && contact.toMm > low)
                contacts.insert(contact.contact);
    }
    return contacts;
}

std::vector<RunExtent> TrainRun::extents(const TrackGraph& graph) const {
    std::vector<RunExtent> extents;
    const std::vector<std::pair<double, double>> covered = coverage();
    for (std::size_t i = 0; i < spans_.size(); ++i) {
        if (covered[i].first >= covered[i].second)
            continue;
        if (spans_[i].isBlock()) {
            const auto [low, high] = inBlock(spans_[i], covered[i].first, covered[i].second);
            extents.push_back({spans_[i].block, 0, 0, false, low, high});
        } else {
            onSteps(graph, spans_[i], covered[i], extents);
        }
    }
    return extents;
}

// The part of each tile of the way between blocks that the train covers, along the tile's leg.
void TrainRun::onSteps(const TrackGraph& graph, const RunSpan& span, std::pair<double, double> covered,
                       std::vector<RunExtent>& extents) {
    double start = 0;
    for (const TrackStep& step : span.steps) {
        const double low = std::max(covered.first, start) - start;
        const double high = std::min(covered.second, start + step.lengthMm) - start;
        start += step.lengthMm;
        if (low >= high)
            continue;
        const trackgraph::Tile& tile = graph.tile(step.tile);
        const bool alongLeg = tile.shape.legs()[step.leg].from == step.entry;
        extents.push_back({0, step.tile, step.leg, tile.shape.isJunction(),
                           alongLeg ? low : step.lengthMm - high, alongLeg ? high : step.lengthMm - low});
    }
}

std::vector<TurnoutUnder> TrainRun::turnoutsUnder(const TrackGraph& graph) const {
    std::vector<TurnoutUnder> turnouts;
    for (const RunExtent& extent : extents(graph))
        if (extent.block == 0 && graph.tile(extent.tile).role() == trackgraph::TileRole::Turnout)
            turnouts.push_back({extent.tile, extent.leg});
    return turnouts;
}

} // namespace stellwerk::sim
