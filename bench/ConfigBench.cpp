// .cs2 reading throughput in MB/s of file bytes: the document model alone, and the document plus the
// typed model, on the largest corpus file of each kind (target: at least 50 MB/s for
// lokomotive.cs2). Input: the shared corpus, read at run time.

#include "cs2config/ConfigFile.h"
#include "cs2config/Document.h"

#include <benchmark/benchmark.h>
#include <fstream>
#include <iterator>
#include <string>

namespace {

using namespace stellwerk;

std::string corpusFile(const char* relative) {
    std::ifstream in(std::string(STELLWERK_SHARED_DIR) + "/corpus/" + relative, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

constexpr const char* locomotives = "bob123456678__TrainControl/test/lokomotive.cs2";
constexpr const char* accessories = "bob123456678__TrainControl/test/magnetartikel.cs2";
constexpr const char* routes = "bob123456678__TrainControl/test/fahrstrassen.cs2";
constexpr const char* page = "GBert__railroad/can2udp/src/gbs-0.cs2";

void parseDocument(benchmark::State& state, const char* file) {
    const std::string bytes = corpusFile(file);
    if (bytes.empty())
        return state.SkipWithError("corpus file missing (STELLWERK_SHARED_DIR)");
    for (auto _ : state) {
        cs2config::Diagnostics diagnostics;
        cs2config::Document document = cs2config::Document::parse(bytes, diagnostics);
        benchmark::DoNotOptimize(document);
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(bytes.size()));
}

void readTypedModel(benchmark::State& state, const char* file) {
    const std::string bytes = corpusFile(file);
    if (bytes.empty())
        return state.SkipWithError("corpus file missing (STELLWERK_SHARED_DIR)");
    for (auto _ : state) {
        cs2config::ConfigFile config = cs2config::ConfigFile::fromBytes(bytes, file);
        benchmark::DoNotOptimize(config);
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(bytes.size()));
}

void writeBack(benchmark::State& state, const char* file) {
    const cs2config::ConfigFile config = cs2config::ConfigFile::fromBytes(corpusFile(file), file);
    const std::size_t size = config.document().serialize().size();
    for (auto _ : state) {
        std::string bytes = config.write();
        benchmark::DoNotOptimize(bytes);
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(size));
}

BENCHMARK_CAPTURE(parseDocument, lokomotive, locomotives);
BENCHMARK_CAPTURE(readTypedModel, lokomotive, locomotives);
BENCHMARK_CAPTURE(readTypedModel, magnetartikel, accessories);
BENCHMARK_CAPTURE(readTypedModel, fahrstrassen, routes);
BENCHMARK_CAPTURE(readTypedModel, gleisbildseite, page);
BENCHMARK_CAPTURE(writeBack, lokomotive, locomotives);

} // namespace

BENCHMARK_MAIN();
