// boxlod's rasterizer against Mesa's llvmpipe on the same scene, in one run:
// ~1M small triangles at 1920x1080 with per-pixel Blinn-Phong.
//   build/experiments/rasterizer_benchmark [--benchmark_filter=...]
// llvmpipe runs with LP_NUM_THREADS set to the thread count of the case.
#include "benchmark_scene.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>

#ifdef BOXLOD_HAVE_OSMESA
#include "llvmpipe_peer.h"
#endif

using namespace boxlod;

namespace {

const Mesh& scene_mesh() {
    static const Mesh mesh = bench::height_field(708);
    return mesh;
}

void boxlod_frame(::benchmark::State& state) {
    int threads = int(state.range(0));
    std::vector<Batch> batches{{&scene_mesh(), Surface{}}};
    batches[0].surface.base_color = {0.7f, 0.6f, 0.5f, 1};
    RenderSettings settings = bench::benchmark_settings(threads);
    Frame frame = make_frame(bench::frame_width, bench::frame_height, {0, 0, 0});
    for (auto _ : state) {
        render(batches, settings, frame);
        ::benchmark::DoNotOptimize(frame.color.data());
    }
    std::size_t covered = 0;
    for (const auto& c : frame.color) covered += c.w() > 0;
    state.counters["covered"] = double(covered) / double(frame.color.size());
    state.counters["Mtri/s"] = ::benchmark::Counter(double(scene_mesh().indices.size() / 3) * 1e-6,
                                                    ::benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(boxlod_frame)->Arg(1)->Arg(2)->Unit(::benchmark::kMillisecond)->UseRealTime()->MinTime(2);

#ifdef BOXLOD_HAVE_OSMESA
void llvmpipe_frame(::benchmark::State& state) {
    int threads = int(state.range(0));
    auto peer = bench::LlvmpipePeer::create(scene_mesh(), bench::benchmark_settings(threads), threads);
    if (!peer) {
        state.SkipWithError("OSMesa/llvmpipe context could not be created");
        return;
    }
    for (auto _ : state) peer->draw();
    state.counters["covered"] = peer->covered_fraction();
    state.counters["Mtri/s"] = ::benchmark::Counter(double(scene_mesh().indices.size() / 3) * 1e-6,
                                                    ::benchmark::Counter::kIsIterationInvariantRate);
}
#endif

}  // namespace

int main(int argc, char** argv) {
    // llvmpipe reads its thread count once per process, before the first context.
    if (!std::getenv("LP_NUM_THREADS")) setenv("LP_NUM_THREADS", "2", 1);
#ifdef BOXLOD_HAVE_OSMESA
    ::benchmark::RegisterBenchmark("llvmpipe_frame", llvmpipe_frame)
        ->Arg(std::atoi(std::getenv("LP_NUM_THREADS")))
        ->Unit(::benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(2);
#endif
    ::benchmark::Initialize(&argc, argv);
    ::benchmark::RunSpecifiedBenchmarks();
    ::benchmark::Shutdown();
}
