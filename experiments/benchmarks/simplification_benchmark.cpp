// The simplification baseline against its peer: meshoptimizer's quadric edge
// collapse (boxlod simplify) and CGAL's Surface_mesh_simplification edge
// collapse with the Garland-Heckbert and Lindstrom-Turk policies, on the
// `manual` sample at 50%, 10% and 1% of its triangles. Counters: the faces
// asked for and achieved. Built on request only (CGAL is slow to compile):
//   cmake --build build --target simplification_benchmark
//   build/experiments/simplification_benchmark
// meshoptimizer is timed for the whole of simplify_model on one thread
// (merging, welding, compacting included); CGAL for edge_collapse alone, on a
// fresh copy of a mesh welded by position (it keeps no uvs, so it has no seams
// to respect). The first argument is the ratio in per mille; meshoptimizer's
// second says whether vertex clustering finishes what edge collapse cannot
// (boxlod simplify's default).
#include "data_gen/interpreter.h"
#include "data_gen/samples.h"
#include "toolkit/lod/hybrid/simplification.h"
#include "toolkit/model/statistics.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <benchmark/benchmark.h>

using namespace boxlod;

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMS = CGAL::Surface_mesh_simplification;
namespace PMP = CGAL::Polygon_mesh_processing;

const Model& manual_sample() {
    static const Model model = generate_building(sample_grammar("manual"), BuildingOptions{});
    return model;
}

std::size_t target_of(const benchmark::State& state) {
    return std::size_t(double(mesh_counts(manual_sample()).triangles) * double(state.range(0)) / 1000);
}

void set_counters(benchmark::State& state, std::size_t faces) {
    state.counters["faces_original"] = double(mesh_counts(manual_sample()).triangles);
    state.counters["faces_target"] = double(target_of(state));
    state.counters["faces"] = double(faces);
}

// The sample's triangles as one CGAL mesh: duplicate points merged, then
// non-manifold vertices split so every edge collapse is well defined.
const Mesh& manual_mesh() {
    static const Mesh mesh = [] {
        std::vector<Kernel::Point_3> points;
        std::vector<std::vector<std::size_t>> triangles;
        for (const Node& node : manual_sample().nodes)
            for (const Primitive& p : node.primitives) {
                std::size_t base = points.size();
                for (const auto& v : p.positions) points.emplace_back(v.x(), v.y(), v.z());
                for (std::size_t i = 0; i < p.indices.size(); i += 3)
                    triangles.push_back(
                        {base + p.indices[i], base + p.indices[i + 1], base + p.indices[i + 2]});
            }
        PMP::repair_polygon_soup(points, triangles);
        PMP::orient_polygon_soup(points, triangles);
        Mesh result;
        PMP::polygon_soup_to_polygon_mesh(points, triangles, result);
        return result;
    }();
    return mesh;
}

// Edge_collapse counts edges; the budget here is faces.
struct FaceCountStop {
    const Mesh* mesh;
    std::size_t target;
    template <typename Profile>
    bool operator()(const double&, const Profile&, std::size_t, std::size_t) const {
        return mesh->number_of_faces() <= target;
    }
};

template <typename Collapse>
void run_cgal(benchmark::State& state, Collapse collapse) {
    std::size_t faces = 0;
    for (auto _ : state) {
        state.PauseTiming();
        Mesh mesh = manual_mesh();
        state.ResumeTiming();
        collapse(mesh, FaceCountStop{&mesh, target_of(state)});
        faces = mesh.number_of_faces();
    }
    set_counters(state, faces);
}

void bm_meshoptimizer(benchmark::State& state) {
    SimplifyOptions options;
    options.threads = 1;
    options.clustering_fallback = state.range(1) != 0;
    std::size_t faces = 0;
    for (auto _ : state)
        faces = mesh_counts(simplify_model(manual_sample(), target_of(state), options)).faces;
    set_counters(state, faces);
}

void bm_cgal_garland_heckbert(benchmark::State& state) {
    run_cgal(state, [](Mesh& mesh, const FaceCountStop& stop) {
        SMS::GarlandHeckbert_plane_policies<Mesh, Kernel> policies(mesh);
        SMS::edge_collapse(
            mesh, stop,
            CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
    });
}

void bm_cgal_lindstrom_turk(benchmark::State& state) {
    run_cgal(state, [](Mesh& mesh, const FaceCountStop& stop) {
        SMS::edge_collapse(mesh, stop,
                           CGAL::parameters::get_cost(SMS::LindstromTurk_cost<Mesh>())
                               .get_placement(SMS::LindstromTurk_placement<Mesh>()));
    });
}

void ratios(benchmark::internal::Benchmark* b) {
    for (int per_mille : {500, 100, 10}) b->Args({per_mille});
    b->Unit(benchmark::kMillisecond);
}

void ratios_and_fallback(benchmark::internal::Benchmark* b) {
    for (int per_mille : {500, 100, 10})
        for (int fallback : {0, 1}) b->Args({per_mille, fallback});
    b->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK(bm_meshoptimizer)->Apply(ratios_and_fallback);
BENCHMARK(bm_cgal_garland_heckbert)->Apply(ratios);
BENCHMARK(bm_cgal_lindstrom_turk)->Apply(ratios);
BENCHMARK_MAIN();
