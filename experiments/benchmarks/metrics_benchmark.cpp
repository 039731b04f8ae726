// What the image metrics cost next to rendering: each metric on a pair of
// 512x512 and 1920x1080 images (a render of the FZK-Haus and the same view
// from 5% farther away), and the render itself for scale.
//   build/experiments/metrics_benchmark [--benchmark_filter=...]
// The second argument of every case is the thread count. bm_sweep_rows
// draws a sweep's rows one at a time or side by side (experiments/sweep/sweep.cpp: draw_rows).
#include "toolkit/drawing/drawable.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/metrics/flip.h"
#include "toolkit/metrics/image_metrics.h"
#include "toolkit/metrics/silhouette.h"
#include "toolkit/model/framing.h"

#include "base/parallel.h"

#include <benchmark/benchmark.h>

#include <map>
#include <memory>

using namespace boxlod;

namespace {

const char* fzk_haus_ifc = "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc";

const DrawableModel& house() {
    static const std::unique_ptr<DrawableModel> drawable = make_drawable_model(load_model(fzk_haus_ifc));
    return *drawable;
}

// The view `boxlod render` takes by default (+X+Y+Z, fovy 45, framed), `distance_scale` times as far.
RenderSettings house_view(double distance_scale, int threads, const Eigen::Vector3f& direction = {1, 1, 1}) {
    const Framing framing = framing_of(house().drawable.bounds);
    RenderSettings settings;
    settings.camera =
        framed_camera(framing, direction, float(framing_distance(framing, 45) * distance_scale), 45);
    settings.light = light_for_camera(settings.camera);
    settings.light.shininess = 0;  // the material's
    settings.threads = threads;
    return settings;
}

Image8 render_house(int width, int height, double distance_scale, int threads,
                    const Eigen::Vector3f& direction = {1, 1, 1}) {
    Frame frame = make_frame(width, height, {1, 1, 1});
    render(house().drawable.batches, house_view(distance_scale, threads, direction), frame);
    return frame_to_srgb8(frame);
}

// The pair of images for one size, rendered once.
const std::pair<Image8, Image8>& image_pair(int width, int height) {
    static std::map<std::pair<int, int>, std::pair<Image8, Image8>> cache;
    auto key = std::pair{width, height};
    if (!cache.count(key))
        cache[key] = {render_house(width, height, 1.0, 0), render_house(width, height, 1.05, 0)};
    return cache[key];
}

void set_pixels(benchmark::State& state) {
    state.counters["Mpixel/s"] = benchmark::Counter(double(state.range(0)) * double(state.range(1)) * 1e-6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
}

void bm_render(benchmark::State& state) {
    int width = int(state.range(0)), height = int(state.range(1)), threads = int(state.range(2));
    RenderSettings settings = house_view(1.0, threads);
    Frame frame = make_frame(width, height, {1, 1, 1});
    for (auto _ : state) {
        frame = make_frame(width, height, {1, 1, 1});
        render(house().drawable.batches, settings, frame);
        benchmark::DoNotOptimize(frame.color.data());
    }
    set_pixels(state);
}

void bm_rmse_psnr(benchmark::State& state) {
    const auto& [a, b] = image_pair(int(state.range(0)), int(state.range(1)));
    for (auto _ : state) benchmark::DoNotOptimize(psnr(a, b));
    set_pixels(state);
}

void bm_ssim(benchmark::State& state) {
    const auto& [a, b] = image_pair(int(state.range(0)), int(state.range(1)));
    for (auto _ : state) benchmark::DoNotOptimize(ssim(a, b, int(state.range(2))));
    set_pixels(state);
}

void bm_flip(benchmark::State& state) {
    const auto& [a, b] = image_pair(int(state.range(0)), int(state.range(1)));
    for (auto _ : state) benchmark::DoNotOptimize(flip(a, b, 67, int(state.range(2))).mean);
    set_pixels(state);
}

// What a sweep pays per LoD: the original's half is prepared once per view.
void bm_flip_prepared(benchmark::State& state) {
    const auto& [a, b] = image_pair(int(state.range(0)), int(state.range(1)));
    const FlipReference reference = prepare_flip_reference(a, 67, int(state.range(2)));
    for (auto _ : state) benchmark::DoNotOptimize(flip(reference, b, int(state.range(2))).mean);
    set_pixels(state);
}

void bm_iou(benchmark::State& state) {
    const auto& [a, b] = image_pair(int(state.range(0)), int(state.range(1)));
    for (auto _ : state)
        benchmark::DoNotOptimize(silhouette_iou(coverage_from_background(a, {255, 255, 255}),
                                                coverage_from_background(b, {255, 255, 255})));
    set_pixels(state);
}

// A sweep's rows at 256x256, 2 threads: the house 5 % farther away from each
// of the 26 views, rendered and compared by FLIP with the view's prepared
// original. side_by_side = 0: one row at a time, both threads on its render
// and FLIP (as sweeps drew before); 1: each row on one thread, two rows at once.
void bm_sweep_rows(benchmark::State& state) {
    const int side = int(state.range(0));
    const bool side_by_side = state.range(1) != 0;
    std::vector<Eigen::Vector3f> directions;
    for (const std::string& name : camera_position_names()) directions.push_back(*camera_direction(name));
    std::vector<FlipReference> references;
    for (const Eigen::Vector3f& direction : directions)
        references.push_back(prepare_flip_reference(render_house(side, side, 1.0, 0, direction), 67, 0));
    std::vector<double> means(directions.size());
    auto row = [&](std::size_t r, int threads) {
        means[r] = flip(references[r], render_house(side, side, 1.05, threads, directions[r]), threads).mean;
    };
    for (auto _ : state) {
        if (side_by_side)
            parallel_for(directions.size(), 2, [&](std::size_t r) { row(r, 1); });
        else
            for (std::size_t r = 0; r < directions.size(); ++r) row(r, 2);
        benchmark::DoNotOptimize(means.data());
    }
    state.counters["rows/s"] =
        benchmark::Counter(double(directions.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void sizes_and_threads(benchmark::internal::Benchmark* b) {
    for (auto [w, h] : {std::pair{64, 64}, std::pair{256, 256}, std::pair{512, 512}, std::pair{1920, 1080}})
        for (int threads : {1, 2}) b->Args({w, h, threads});
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

void sizes(benchmark::internal::Benchmark* b) {
    for (auto [w, h] : {std::pair{512, 512}, std::pair{1920, 1080}}) b->Args({w, h});
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

}  // namespace

BENCHMARK(bm_render)->Apply(sizes_and_threads);
BENCHMARK(bm_rmse_psnr)->Apply(sizes);
BENCHMARK(bm_ssim)->Apply(sizes_and_threads);
BENCHMARK(bm_flip)->Apply(sizes_and_threads);
BENCHMARK(bm_flip_prepared)->Apply(sizes_and_threads);
BENCHMARK(bm_iou)->Apply(sizes);
BENCHMARK(bm_sweep_rows)->ArgsProduct({{64, 256}, {0, 1}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
