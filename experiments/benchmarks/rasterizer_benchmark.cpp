// boxlod's rasterizer against Mesa's llvmpipe on the same scenes, in one run:
// - frame: ~1M small triangles at 1920x1080 with per-pixel Blinn-Phong;
// - model: real buildings at 1920x1080 in normal mode (colour maps, normal
//   maps, trilinear mip-mapping): the FZK-Haus (IFC by web-ifc, 35,792 faces) and the
//   `manual` sample (19,049 faces), framed from +X+Y+Z.
//   build/experiments/rasterizer_benchmark [--benchmark_filter=...]
// llvmpipe runs with LP_NUM_THREADS set to the thread count of the case.
#include "benchmark_scene.h"
#include "data_gen/interpreter.h"
#include "data_gen/samples.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/model/framing.h"

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

std::vector<Batch> scene_batches() {
    std::vector<Batch> batches{{&scene_mesh(), Surface{}}};
    batches[0].surface.base_color = {0.7f, 0.6f, 0.5f, 1};
    return batches;
}

// The real models, drawable, with the settings both renderers draw them with.
struct RealModel {
    std::unique_ptr<DrawableModel> drawable;
    RenderSettings settings;
};

RealModel make_real_model(const Model& model) {
    RealModel m{make_drawable_model(model), {}};
    Framing framing = framing_of(m.drawable->drawable.bounds);
    m.settings.mode = RenderMode::normal;
    m.settings.camera =
        framed_camera(framing, Eigen::Vector3f(1, 1, 1).normalized(), framing_distance(framing, 45), 45);
    m.settings.light = light_for_camera(m.settings.camera);
    return m;
}

const RealModel& real_model(int index) {
    static const RealModel fzk_haus =
        make_real_model(load_model("/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc"));
    static const RealModel manual =
        make_real_model(generate_building(sample_grammar("manual"), BuildingOptions{}));
    return index == 0 ? fzk_haus : manual;
}

const char* model_names[2] = {"fzk_haus", "manual"};

void draw_with_boxlod(::benchmark::State& state, const std::vector<Batch>& batches, RenderSettings settings,
                      int threads) {
    settings.threads = threads;
    Frame frame = make_frame(bench::frame_width, bench::frame_height, {0, 0, 0});
    for (auto _ : state) {
        render(batches, settings, frame);
        ::benchmark::DoNotOptimize(frame.color.data());
    }
    std::size_t covered = 0;
    for (const auto& c : frame.color) covered += c.w() > 0;
    state.counters["covered"] = double(covered) / double(frame.color.size());
}

void boxlod_frame(::benchmark::State& state) {
    draw_with_boxlod(state, scene_batches(), bench::benchmark_settings(1), int(state.range(0)));
    state.counters["Mtri/s"] = ::benchmark::Counter(double(scene_mesh().indices.size() / 3) * 1e-6,
                                                    ::benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(boxlod_frame)->Arg(1)->Arg(2)->Unit(::benchmark::kMillisecond)->UseRealTime()->MinTime(2);

// Arguments: the model (0 FZK-Haus, 1 manual), threads.
void boxlod_model(::benchmark::State& state) {
    const RealModel& m = real_model(int(state.range(0)));
    state.SetLabel(model_names[state.range(0)]);
    draw_with_boxlod(state, m.drawable->drawable.batches, m.settings, int(state.range(1)));
}
BENCHMARK(boxlod_model)
    ->Args({0, 1})
    ->Args({0, 2})
    ->Args({1, 1})
    ->Args({1, 2})
    ->Unit(::benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2);

#ifdef BOXLOD_HAVE_OSMESA
void draw_with_llvmpipe(::benchmark::State& state, const std::vector<Batch>& batches,
                        const RenderSettings& settings) {
    auto peer = bench::LlvmpipePeer::create(batches, settings, bench::frame_width, bench::frame_height);
    if (!peer) {
        state.SkipWithError("OSMesa/llvmpipe context could not be created");
        return;
    }
    // llvmpipe takes LP_NUM_THREADS once per process: a case run with another
    // count would compare boxlod with a peer of other threads.
    const int threads = bench::LlvmpipePeer::rasterizer_threads(),
              wanted = std::atoi(std::getenv("LP_NUM_THREADS"));
    if (threads != wanted) {
        state.SkipWithError(("llvmpipe runs " + std::to_string(threads) +
                             " rasterizer threads, not LP_NUM_THREADS=" + std::to_string(wanted))
                                .c_str());
        return;
    }
    for (auto _ : state) peer->draw();
    state.counters["covered"] = peer->covered_fraction();
    state.counters["llvmpipe threads"] = threads;
}

void llvmpipe_frame(::benchmark::State& state) {
    draw_with_llvmpipe(state, scene_batches(), bench::benchmark_settings(1));
    state.counters["Mtri/s"] = ::benchmark::Counter(double(scene_mesh().indices.size() / 3) * 1e-6,
                                                    ::benchmark::Counter::kIsIterationInvariantRate);
}

void llvmpipe_model(::benchmark::State& state) {
    const RealModel& m = real_model(int(state.range(0)));
    state.SetLabel(model_names[state.range(0)]);
    draw_with_llvmpipe(state, m.drawable->drawable.batches, m.settings);
}
#endif

}  // namespace

int main(int argc, char** argv) {
    // llvmpipe reads its thread count once per process, before the first context.
    if (!std::getenv("LP_NUM_THREADS")) setenv("LP_NUM_THREADS", "2", 1);
#ifdef BOXLOD_HAVE_OSMESA
    const int threads = std::atoi(std::getenv("LP_NUM_THREADS"));
    ::benchmark::RegisterBenchmark("llvmpipe_frame", llvmpipe_frame)
        ->Arg(threads)
        ->Unit(::benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(2);
    ::benchmark::RegisterBenchmark("llvmpipe_model", llvmpipe_model)
        ->Args({0, threads})
        ->Args({1, threads})
        ->Unit(::benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(2);
#endif
    ::benchmark::Initialize(&argc, argv);
    ::benchmark::RunSpecifiedBenchmarks();
    ::benchmark::Shutdown();
}
