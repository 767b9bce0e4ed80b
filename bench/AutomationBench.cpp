// The automation's path decision (issue 34; target < 5 ms with 100 blocks and 20 trains): on the benchmarks'
// station page (ten parallel tracks of 200 tiles, a contact every 10 tiles, crossovers: about 200 blocks)
// with 20 trains placed and each holding its block, every train chooses its next destination and way, as the
// dispatcher asks when a train is waiting. Prints the median, p99 and worst time of one decision. A plain
// harness printing figures. Run: build/bench/stellwerk-automation-bench

#include "BenchmarkPage.h"
#include "automation/PathChoice.h"
#include "automation/Reservations.h"
#include "automation/Tracking.h"
#include "trackgraph/TrackGraph.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

using namespace stellwerk;
using namespace stellwerk::automation;

namespace {

// What the dispatcher lets a train see: blocks and connections free of others, ghosts and trains.
TrackState stateFor(std::uint32_t locId, const Tracking& tracking, const Reservations& reservations) {
    TrackState state;
    state.blockFree = [&, locId](int block) {
        const std::uint32_t in = tracking.trainIn(block);
        return reservations.blockAvailable(block, locId) && !tracking.isGhost(block) &&
               (in == 0 || in == locId);
    };
    state.connectionFree = [&, locId](int id) { return reservations.connectionAvailable(id, locId); };
    state.trainFacing = [&, locId](int block) -> std::optional<trackgraph::End> {
        const std::uint32_t in = tracking.trainIn(block);
        if (in == 0 || in == locId)
            return std::nullopt;
        return tracking.body(in)->towards;
    };
    return state;
}

} // namespace

int main() {
    const std::vector<cs2config::TrackElement> page = bench::stationPage();
    trackgraph::GraphSource source;
    source.pages.push_back({0, "station", &page});
    const trackgraph::TrackGraph graph = trackgraph::TrackGraph::derive(source);
    const int blocks = int(graph.blocks().size());
    constexpr int Trains = 20;
    Tracking tracking(graph);
    Reservations reservations(graph);
    for (int i = 0; i < Trains; ++i) {
        const int block = 1 + i * blocks / Trains;
        tracking.place(std::uint32_t(i + 1), block, trackgraph::End::B, 200);
        reservations.holdBlock(std::uint32_t(i + 1), block);
    }
    const PathChoice choice(graph);
    std::vector<double> times;
    int found = 0;
    for (int round = 0; round < 50; ++round)
        for (std::uint32_t locId = 1; locId <= Trains; ++locId) {
            const TrainBody* body = tracking.body(locId);
            const auto start = std::chrono::steady_clock::now();
            const std::optional<Path> path = choice.choose({body->frontBlock, body->towards}, 200,
                                                           stateFor(locId, tracking, reservations));
            times.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            found += path.has_value();
        }
    std::sort(times.begin(), times.end());
    std::printf(
        "path decision, %d blocks, %zu connections, %d trains: median %.3f ms, p99 %.3f ms, worst %.3f ms "
        "(target < 5 ms); %d of %zu decisions found a way\n",
        blocks, graph.connections().size(), Trains, times[times.size() / 2], times[times.size() * 99 / 100],
        times.back(), found, times.size());
    return 0;
}
