// City scale (docs/city.md: Memory), in one run:
// - city_levels/N: every level of N buildings of a generated city, built and
//   packed; counters: packed MB and what keeping every level decoded takes
//   (unpacked MB), as boxlod city did before levels were packed.
// - unpack_levels/N: unpacking all of them again, as a frame does for the
//   levels it draws that are not resident: the cost of keeping them packed.
// - select_frame/1000: one frame's selection for 1,000 buildings (texel-exact
//   with hysteresis, along the orbit), the buildings copies of the city's real
//   ones on a grid; the target is under 1 ms.
//   build/experiments/city_benchmark
#include "data_gen/city.h"
#include "experiments/camera_path.h"
#include "experiments/fly_through.h"

#include <benchmark/benchmark.h>

#include <cmath>

using namespace boxlod;

namespace {

constexpr int city_buildings = 25;

Model make_city() {
    CityOptions options;
    options.buildings = city_buildings;
    return generate_city(options);
}

const CityLevels& city_levels() {
    static const CityLevels levels = build_city_levels(make_city(), FlyThroughOptions{}, false);
    return levels;
}

void bm_city_levels(benchmark::State& state) {
    const Model city = make_city();
    FlyThroughOptions options;
    options.threads = 1;
    std::size_t packed = 0, unpacked = 0;
    for (auto _ : state) {
        CityLevels levels = build_city_levels(city, options, false);
        packed = levels.packed_bytes, unpacked = levels.unpacked_bytes;
    }
    state.counters["packed MB"] = double(packed) * 1e-6;
    state.counters["unpacked MB"] = double(unpacked) * 1e-6;
    state.counters["unpacked/packed"] = double(unpacked) / double(packed);
}
BENCHMARK(bm_city_levels)->Arg(city_buildings)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void bm_unpack_levels(benchmark::State& state) {
    const CityLevels& levels = city_levels();
    std::size_t count = 0;
    for (auto _ : state) {
        count = 0;
        for (const BuildingLevels& building : levels.buildings)
            for (const PackedDrawable& level : building.levels) benchmark::DoNotOptimize(unpack_drawable(level)), ++count;
    }
    state.counters["levels"] = double(count);
}
BENCHMARK(bm_unpack_levels)->Arg(city_buildings)->Unit(benchmark::kMillisecond)->UseRealTime();

// `count` selection objects: the city's buildings repeated on a grid, 200 m apart per copy.
std::vector<SelectionObject> copies(const std::vector<SelectionObject>& objects, int count) {
    std::vector<SelectionObject> out;
    int side = int(std::ceil(std::sqrt(double(count) / double(objects.size()))));
    for (int i = 0; out.size() < std::size_t(count); ++i) {
        SelectionObject copy = objects[std::size_t(i) % objects.size()];
        int tile = i / int(objects.size());
        Eigen::Vector3f shift(float(tile % side) * 200, 0, float(tile / side) * 200);
        copy.center += shift;
        if (copy.box) copy.box->center += shift;
        out.push_back(std::move(copy));
    }
    return out;
}

void bm_select_frame(benchmark::State& state) {
    const CityLevels& levels = city_levels();
    const std::vector<SelectionObject> objects = copies(levels.objects, int(state.range(0)));
    Model city = make_city();
    const FlyThroughOptions options;
    const std::vector<CameraPose> path = city_path("orbit", city, options.fovy, 60);
    std::vector<Selector> selectors(objects.size(), Selector{options.hysteresis, -1});
    std::vector<int> chosen(objects.size());
    std::size_t frame = 0;
    for (auto _ : state) {
        SelectionView view{pose_camera(path[frame++ % path.size()], levels.bounds, options.fovy), options.width,
                           options.height};
        for (std::size_t b = 0; b < objects.size(); ++b) chosen[b] = select_level(selectors[b], options.strategy, objects[b], view);
        benchmark::DoNotOptimize(chosen.data());
    }
    state.counters["buildings"] = double(objects.size());
}
BENCHMARK(bm_select_frame)->Arg(1000)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
