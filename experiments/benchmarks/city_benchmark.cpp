// City scale (docs/city.md: Memory), in one run:
// - city_levels/N/K: the levels of a generated city of N buildings drawing from
//   K designs (0: each its own), built and packed; counters: ms per building,
//   LoDs built, packed MB, what keeping every level decoded would take
//   (unpacked MB), and the process's peak resident MB so far.
// - unpack_levels/N: unpacking all levels of N = 25 buildings again, as a frame does
//   for the levels it draws that are not resident: the cost of keeping them packed.
// - select_frame/N: one frame's selection for N buildings (texel-exact
//   with hysteresis, along the orbit), the buildings copies of the city's real
//   ones on a grid; the target is under 1 ms at 10,000.
//   build/experiments/city_benchmark
#include "data_gen/city.h"
#include "experiments/city/camera_path.h"
#include "experiments/city/fly_through.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <string>

using namespace boxlod;

namespace {

constexpr int city_buildings = 25;

CityPlan make_city(int buildings = city_buildings, int designs = 0) {
    CityOptions options;
    options.buildings = buildings;
    options.designs = designs;
    return plan_city(options);
}

const CityLevels& city_levels() {
    static const CityLevels levels = build_city_levels(make_city(), FlyThroughOptions{}, false);
    return levels;
}

// The process's peak resident set (VmHWM), in MB.
double peak_resident_mb() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024e-6;
    return 0;
}

void bm_city_levels(benchmark::State& state) {
    const CityPlan city = make_city(int(state.range(0)), int(state.range(1)));
    FlyThroughOptions options;
    std::size_t packed = 0, unpacked = 0, lods = 0;
    for (auto _ : state) {
        CityLevels levels = build_city_levels(city, options, false);
        packed = levels.packed_bytes;
        unpacked = levels.unpacked_bytes;
        lods = levels.designs.size();
    }
    // kIsRate | kInvert: seconds over the count, here per building in ms.
    state.counters["ms per building"] =
        benchmark::Counter(double(state.iterations()) * double(city.lots.size()) * 1e-3,
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["LoDs built"] = double(lods);
    state.counters["packed MB"] = double(packed) * 1e-6;
    state.counters["unpacked MB"] = double(unpacked) * 1e-6;
    state.counters["peak resident MB"] = peak_resident_mb();
}
// A sweep of buildings: unique at 25 (unpack_levels' city), 100 and 1,000, then
// 1,000 and 10,000 lots drawing from 100 designs (10,000 unique: docs/city.md, Scale).
BENCHMARK(bm_city_levels)
    ->Args({city_buildings, 0})
    ->Args({100, 0})
    ->Args({1000, 0})
    ->Args({1000, 100})
    ->Args({10000, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

void bm_unpack_levels(benchmark::State& state) {
    const CityLevels& levels = city_levels();
    std::size_t count = 0;
    for (auto _ : state) {
        count = 0;
        for (const DesignLevels& design : levels.designs)
            for (const PackedDrawable& level : design.levels) {
                benchmark::DoNotOptimize(unpack_drawable(level));
                ++count;
            }
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
    const FlyThroughOptions options;
    const std::vector<CameraPose> path = city_path("orbit", make_city(), levels.bounds, options.fovy, 60);
    std::vector<Selector> selectors(objects.size(), Selector{options.hysteresis, -1});
    std::vector<int> chosen(objects.size());
    std::size_t frame = 0;
    for (auto _ : state) {
        SelectionView view{pose_camera(path[frame++ % path.size()], levels.bounds, options.fovy),
                           options.width, options.height};
        for (std::size_t b = 0; b < objects.size(); ++b)
            chosen[b] = select_level(selectors[b], options.strategy, objects[b], view);
        benchmark::DoNotOptimize(chosen.data());
    }
    state.counters["buildings"] = double(objects.size());
}
BENCHMARK(bm_select_frame)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
