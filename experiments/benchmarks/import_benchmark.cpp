// Reading a model through assimp: in this process, against the isolated read
// every command does (a child process under limits that hands the scene back,
// base/child_process.h, toolkit/formats/model_bytes.h), on the FZK-Haus IFC (Debian's
// assimp-testmodels). Issue 47's target: isolation under 10 % of the import.
//   build/experiments/import_benchmark
#include "toolkit/formats/assimp_io.h"
#include "toolkit/formats/model_bytes.h"

#include <benchmark/benchmark.h>

#include <filesystem>

using namespace boxlod;

namespace {

const char* const fzk = "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc";

template <Model (*Import)(const std::string&)>
void BM_ImportFzkHaus(benchmark::State& state) {
    if (!std::filesystem::exists(fzk)) {
        state.SkipWithError("no FZK-Haus IFC (Debian assimp-testmodels)");
        return;
    }
    std::size_t triangles = 0;
    for (auto _ : state) {
        Model model = Import(fzk);
        triangles = 0;
        for (const Node& node : model.nodes)
            for (const Primitive& p : node.primitives) triangles += p.triangle_count();
        benchmark::DoNotOptimize(triangles);
    }
    state.counters["triangles"] = double(triangles);
}

// What isolation adds besides the fork: the scene to bytes and back.
Model through_bytes(const std::string& path) {
    static const Model model = import_with_assimp_in_process(path);
    return model_from_bytes(model_bytes(model));
}

}  // namespace

BENCHMARK(BM_ImportFzkHaus<through_bytes>)->Name("import_fzk_haus/bytes_round_trip")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ImportFzkHaus<import_with_assimp_in_process>)->Name("import_fzk_haus/in_process")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ImportFzkHaus<import_with_assimp>)->Name("import_fzk_haus/isolated")->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
