// Config-data stream throughput in MB/s of file contents: frames decoded and reassembled, CRC
// checked and the file inflated (target: at least 100 MB/s), and the sender for comparison. Input:
// the 108-loco lokomotive.cs2 of the shared corpus, read at run time.

#include "cs2/Codec.h"
#include "cs2config/ConfigStreamReceiver.h"
#include "cs2config/ConfigStreamSender.h"

#include <benchmark/benchmark.h>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using namespace stellwerk;

std::string locoList() {
    std::ifstream in(std::string(STELLWERK_SHARED_DIR) +
                         "/corpus/bob123456678__TrainControl/test/lokomotive.cs2",
                     std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Decodes every frame and feeds it to the receiver, as a station does on arrival.
void receive(benchmark::State& state, cs2config::StreamFormat format) {
    const std::string contents = locoList();
    if (contents.empty()) {
        state.SkipWithError("corpus file lokomotive.cs2 missing (STELLWERK_SHARED_DIR)");
        return;
    }
    const auto frames = cs2config::streamFrames(contents, format, cs2config::StreamAddress::reply(0x4711));
    cs2config::ConfigStreamReceiver receiver;
    for (auto _ : state) {
        std::size_t received = 0;
        for (const auto& frame : frames) {
            const auto message = cs2::decode(frame);
            for (auto& outcome : receiver.feed(std::get<cs2::ConfigDataStream>(message->body), message->hash))
                received += outcome ? outcome->contents.size() : 0;
        }
        if (received != contents.size())
            state.SkipWithError("the stream did not come back intact");
        benchmark::DoNotOptimize(received);
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(contents.size()));
    state.counters["frames"] = double(frames.size());
}

void BM_ReceiveCompressedLocoList(benchmark::State& state) {
    receive(state, cs2config::StreamFormat::Compressed);
}
BENCHMARK(BM_ReceiveCompressedLocoList);

void BM_ReceiveMs2TextLocoList(benchmark::State& state) {
    receive(state, cs2config::StreamFormat::Ms2Text);
}
BENCHMARK(BM_ReceiveMs2TextLocoList);

void BM_SendCompressedLocoList(benchmark::State& state) {
    const std::string contents = locoList();
    for (auto _ : state) {
        auto frames = cs2config::streamFrames(contents, cs2config::StreamFormat::Compressed,
                                              cs2config::StreamAddress::reply(0x4711));
        benchmark::DoNotOptimize(frames);
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(contents.size()));
}
BENCHMARK(BM_SendCompressedLocoList);

} // namespace

BENCHMARK_MAIN();
