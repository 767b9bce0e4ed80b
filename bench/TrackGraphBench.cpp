// The track graph's derivation (issue 33; target: well under a frame, < 20 ms for 2,000 tiles, memory
// linear in the tiles):
//   1. the benchmarks' 2,000-tile page (every type and rotation, as the track plan bench draws it),
//   2. a station of 2,000 tiles: ten parallel tracks of 200 tiles with a contact every 10 tiles, signals
//      and crossovers between neighbouring tracks (many blocks, turnouts and ways),
//   3. every real page of ../shared/corpus and the demo layout.
// Prints the median and worst time of a derivation and the memory the graph keeps per tile (and the peak
// while deriving), counted by this program's operator new with the sizes malloc gives the blocks. A plain
// harness printing figures. Run: build/bench/stellwerk-trackgraph-bench

#include "BenchmarkPage.h"
#include "cs2config/ConfigFile.h"
#include "cs2config/LayoutFolder.h"
#include "trackgraph/TrackGraph.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <malloc.h>
#include <new>
#include <string>
#include <vector>

using namespace stellwerk;

namespace {

std::atomic<std::size_t> liveBytes{0};
std::atomic<std::size_t> peakBytes{0};

struct Figures {
    double medianMs = 0;
    double worstMs = 0;
    std::size_t keptBytes = 0;
    std::size_t peakBytes = 0;
    std::size_t blocks = 0;
    std::size_t connections = 0;
    std::size_t problems = 0;
};

Figures measure(const trackgraph::GraphSource& source, int runs) {
    Figures figures;
    std::vector<double> times;
    for (int run = 0; run < runs; ++run) {
        const std::size_t before = liveBytes.load();
        peakBytes = before;
        const auto start = std::chrono::steady_clock::now();
        const trackgraph::TrackGraph graph = trackgraph::TrackGraph::derive(source);
        times.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        figures.keptBytes = liveBytes.load() - before;
        figures.peakBytes = peakBytes.load() - before;
        figures.blocks = graph.blocks().size();
        figures.connections = graph.connections().size();
        figures.problems = graph.problems().size();
    }
    std::sort(times.begin(), times.end());
    figures.medianMs = times[times.size() / 2];
    figures.worstMs = times.back();
    return figures;
}

void print(const char* name, const trackgraph::GraphSource& source, int runs) {
    std::size_t tiles = 0;
    for (const trackgraph::SourcePage& page : source.pages)
        tiles += page.elements ? page.elements->size() : 0;
    const Figures f = measure(source, runs);
    const double perTile = tiles ? double(f.keptBytes) / double(tiles) : 0.0;
    std::printf("%-44s %5zu tiles  median %7.3f ms  worst %7.3f ms  %6.0f bytes/tile kept (peak %zu KiB)  "
                "%zu blocks, %zu connections, %zu problems\n",
                name, tiles, f.medianMs, f.worstMs, perTile, f.peakBytes / 1024, f.blocks, f.connections,
                f.problems);
}

void printFolder(const std::string& name, const std::filesystem::path& folder) {
    const cs2config::LayoutFolder::Content content = cs2config::LayoutFolder::open(folder);
    if (!content.problem.empty()) {
        std::printf("%-44s missing: %s\n", name.c_str(), content.problem.c_str());
        return;
    }
    const cs2config::ConfigFile routes =
        cs2config::ConfigFile::load(content.configDirectory / "fahrstrassen.cs2");
    print(name.c_str(),
          trackgraph::GraphSource::of(content.layout, content.accessories ? &*content.accessories : nullptr,
                                      routes.model<cs2config::RouteFile>()),
          50);
}

void printPageFile(const std::string& name, const std::filesystem::path& file) {
    const cs2config::ConfigFile config = cs2config::ConfigFile::load(file);
    const cs2config::TrackPage* page = config.model<cs2config::TrackPage>();
    if (!page) {
        std::printf("%-44s missing or not a page\n", name.c_str());
        return;
    }
    trackgraph::GraphSource source;
    source.pages.push_back({0, name, &page->elements});
    print(name.c_str(), source, 50);
}

} // namespace

// Every heap block counted with the size malloc gave it (what it really takes).
void* operator new(std::size_t size) {
    void* block = std::malloc(size ? size : 1);
    if (!block)
        throw std::bad_alloc();
    const std::size_t live = liveBytes.fetch_add(malloc_usable_size(block)) + malloc_usable_size(block);
    std::size_t peak = peakBytes.load();
    while (live > peak && !peakBytes.compare_exchange_weak(peak, live)) {
    }
    return block;
}

void operator delete(void* block) noexcept {
    if (!block)
        return;
    liveBytes.fetch_sub(malloc_usable_size(block));
    std::free(block);
}

void operator delete(void* block, std::size_t) noexcept {
    operator delete(block);
}

int main() {
    std::printf("Track graph derivation (target: < 20 ms for 2,000 tiles; memory linear in the tiles)\n");
    const std::vector<cs2config::TrackElement> typesPage = bench::benchmarkPage(false);
    trackgraph::GraphSource types;
    types.pages.push_back({0, "bench", &typesPage});
    print("benchmark page (every type and rotation)", types, 100);
    const std::vector<cs2config::TrackElement> station = bench::stationPage();
    trackgraph::GraphSource stationSource;
    stationSource.pages.push_back({0, "station", &station});
    print("station (10 tracks x 200 tiles, crossovers)", stationSource, 100);
    const std::filesystem::path corpus = std::filesystem::path(STELLWERK_SHARED_DIR) / "corpus";
    printFolder("demo layout (3 pages)", STELLWERK_DEMO_LAYOUT_DIR);
    printFolder("corpus karben.cs2", corpus / "GBert__railroad/can2udp/files/maerklin");
    printFolder("corpus TrainControl sample (5 - Test.cs2)",
                corpus / "bob123456678__TrainControl/cs2_sample_layout");
    printPageFile("corpus gbs-0.cs2 (S88 display)", corpus / "GBert__railroad/can2udp/src/gbs-0.cs2");
    return 0;
}
