// Codec throughput: decoded and encoded frames per second on one core, and heap allocations per
// decoded frame (target: at least 10 million decodes per second and zero allocations).

#include "can/FrameText.h"
#include "cs2/Codec.h"

#include <atomic>
#include <benchmark/benchmark.h>
#include <cstdlib>
#include <new>
#include <vector>

namespace {

std::atomic<std::size_t> allocations{0};

// A mix like a busy layout: throttles, functions, turnouts, feedback, status readings, pings,
// config-stream data and an unknown command.
std::vector<stellwerk::can::CanFrame> busTraffic() {
    const char* lines[] = {"00084711 6 00 00 C0 03 01 20",
                           "00094711 6 00 00 40 05 02 58",
                           "000C4711 6 00 00 40 05 03 01",
                           "000B4711 5 00 00 C0 03 01",
                           "00164711 6 00 00 30 04 01 01",
                           "00174711 8 00 00 38 0B 00 01 00 0A",
                           "00234711 8 00 01 00 05 00 01 00 0A",
                           "00014711 8 43 53 32 08 0B 01 00 03",
                           "00314711 8 47 43 F5 DA 01 3E 00 10",
                           "00420300 8 78 9C 8B 4E CF 49 CD 2C",
                           "00004711 5 00 00 00 00 01",
                           "00604711 6 00 01 41 31 01 00",
                           "003B0301 8 03 00 00 00 00 00 00 00",
                           "00104711 8 00 00 C0 03 00 1D 06 A0",
                           "00FE4711 3 01 02 03",
                           "00084711 5 00 00 C0 03 01"};
    std::vector<stellwerk::can::CanFrame> frames;
    for (int repeat = 0; repeat < 256; ++repeat)
        for (const char* line : lines)
            frames.push_back(stellwerk::can::parseFrame(line)->frame);
    return frames;
}

// Heap allocations made by `work` over every frame, counted outside the timed loop so that the
// benchmark library's own bookkeeping does not blur the figure.
template <class Frames, class Work>
double allocationsPerFrame(const Frames& frames, Work work) {
    const std::size_t before = allocations.load();
    for (const auto& frame : frames)
        work(frame);
    return double(allocations.load() - before) / double(frames.size());
}

void BM_Decode(benchmark::State& state) {
    const auto frames = busTraffic();
    std::size_t i = 0;
    for (auto _ : state) {
        auto result = stellwerk::cs2::decode(frames[i]);
        benchmark::DoNotOptimize(result);
        i = (i + 1) % frames.size();
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["allocations_per_frame"] = allocationsPerFrame(frames, [](const auto& frame) {
        auto result = stellwerk::cs2::decode(frame);
        benchmark::DoNotOptimize(result);
    });
}
BENCHMARK(BM_Decode);

void BM_Encode(benchmark::State& state) {
    std::vector<stellwerk::cs2::Message> messages;
    for (const auto& frame : busTraffic())
        if (auto result = stellwerk::cs2::decode(frame))
            messages.push_back(*result);
    std::size_t i = 0;
    for (auto _ : state) {
        auto frame = stellwerk::cs2::encode(messages[i]);
        benchmark::DoNotOptimize(frame);
        i = (i + 1) % messages.size();
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["allocations_per_frame"] = allocationsPerFrame(messages, [](const auto& message) {
        auto frame = stellwerk::cs2::encode(message);
        benchmark::DoNotOptimize(frame);
    });
}
BENCHMARK(BM_Encode);

void BM_NetworkFormRoundTrip(benchmark::State& state) {
    const auto frames = busTraffic();
    std::size_t i = 0;
    for (auto _ : state) {
        const auto bytes = frames[i].toNetwork();
        auto frame = stellwerk::can::CanFrame::fromNetwork(bytes);
        benchmark::DoNotOptimize(frame);
        i = (i + 1) % frames.size();
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_NetworkFormRoundTrip);

} // namespace

void* operator new(std::size_t size) {
    allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}

BENCHMARK_MAIN();
