#include "toolkit/lod/hybrid/simplification.h"

#include "base/input_error.h"
#include "base/parallel.h"
#include "toolkit/lod/hybrid/draw_calls.h"
#include "toolkit/model/model_subtree.h"
#include "toolkit/model/vertex_layout.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <compare>
#include <limits>
#include <map>
#include <numeric>

namespace boxlod {
namespace {

// Drops the vertices the simplified indices no longer use.
void compact(Primitive& mesh) {
    std::vector<unsigned> remap(mesh.positions.size());
    std::size_t unique = meshopt_optimizeVertexFetchRemap(remap.data(), mesh.indices.data(),
                                                          mesh.indices.size(), mesh.positions.size());
    remap_vertices(mesh, remap, unique);
}

using Indices = std::vector<unsigned>;

// No error bound: the face budget alone decides, as for the LoD levels it is compared with.
constexpr float no_error_limit = std::numeric_limits<float>::max();

Indices collapse_edges(const Primitive& mesh, const Indices& indices, std::size_t target_triangles,
                       unsigned flags) {
    Indices out(indices.size());
    out.resize(meshopt_simplify(out.data(), indices.data(), indices.size(), mesh.positions[0].data(),
                                mesh.positions.size(), sizeof(Eigen::Vector3f), target_triangles * 3,
                                no_error_limit, flags, nullptr));
    return out;
}

// Vertex clustering with the most triangles not above the target: the
// clustering grid only roughly follows the count asked for, so the count asked
// for is searched. Empty when every clustering removes everything.
Indices cluster_vertices(const Primitive& mesh, const Indices& indices, std::size_t target_triangles) {
    Indices best, out(indices.size());
    std::size_t low = target_triangles, high = indices.size() / 3;
    for (int step = 0; step < 16 && low <= high; ++step) {
        std::size_t ask = low + (high - low) / 2;
        out.resize(indices.size());
        out.resize(meshopt_simplifySloppy(out.data(), indices.data(), indices.size(),
                                          mesh.positions[0].data(), mesh.positions.size(),
                                          sizeof(Eigen::Vector3f), ask * 3, no_error_limit, nullptr));
        if (out.size() <= target_triangles * 3) {
            if (out.size() > best.size()) best = out;
            low = ask + 1;
        } else {
            if (ask == 0) break;
            high = ask - 1;
        }
    }
    return best;
}

// Whether the budget is always reached (possibly by clustering).
bool clusters(const SimplifyOptions& options) {
    return options.clustering_fallback || !options.edge_collapse;
}

// Whether a position of the welded mesh carries two normals (apart by more
// than rounding: cos 0.8 degrees): a faceted part, flat-shaded as IFC's are.
// meshoptimizer 0.18 collapses by position and leaves each kept position one
// of its vertices for every face around it, so such a part's normals come out
// arbitrary (a wall shaded as the roof).
bool faceted(const Primitive& welded) {
    if (welded.normals.empty()) return false;
    std::map<std::array<float, 3>, Eigen::Vector3f> normal_at;
    for (std::size_t v = 0; v < welded.positions.size(); ++v) {
        const Eigen::Vector3f &p = welded.positions[v], &n = welded.normals[v];
        const auto [at, added] = normal_at.try_emplace({p.x(), p.y(), p.z()}, n);
        if (!added && at->second.dot(n) < 0.9999f * at->second.norm() * n.norm()) return true;
    }
    return false;
}

// The welded mesh with at most `target_triangles` triangles when the fallback
// is on (possibly none: parts too small to cluster vanish). A faceted mesh
// whose material maps no normals (normal-mapped parts keep theirs) comes
// out flat-shaded, without normals (glTF 2.0, 3.7.2.1: the client computes
// flat normals), welded by position and uv: by ꟻLIP and bytes both better
// than its normals as the collapse leaves them (docs/cost.md: Each budget at equal bytes).
Primitive simplify_mesh(const Primitive& welded, bool flat, std::size_t target_triangles,
                        const SimplifyOptions& options) {
    Primitive mesh = welded;
    if (mesh.triangle_count() > target_triangles) {
        const unsigned flags = options.lock_border ? meshopt_SimplifyLockBorder : 0;
        const std::size_t target_indices = target_triangles * 3;
        Indices out = options.edge_collapse ? collapse_edges(mesh, mesh.indices, target_triangles, flags)
                                            : mesh.indices;
        if (clusters(options) && out.size() > target_indices)
            out = cluster_vertices(mesh, out, target_triangles);
        mesh.indices = std::move(out);
        compact(mesh);
        if (flat) {  // tangents, unused without a normal map, go too (glTF 2.0, 3.7.2.1)
            mesh.normals.clear();
            mesh.tangents.clear();
            weld(mesh);
        }
    }
    mesh.polygon_count = mesh.triangle_count();
    return mesh;
}

double surface_area(const Primitive& mesh) {
    double area = 0;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const Eigen::Vector3f &a = mesh.positions[mesh.indices[i]], &b = mesh.positions[mesh.indices[i + 1]],
                              &c = mesh.positions[mesh.indices[i + 2]];
        area += 0.5 * double((b - a).cross(c - a).norm());
    }
    return area;
}

// Splits `total` over `weights` in proportion, by largest remainder: the parts
// sum to `total` exactly and ties go to the earlier group.
std::vector<std::size_t> proportional_budget(std::size_t total, const std::vector<double>& weights) {
    double sum = std::accumulate(weights.begin(), weights.end(), 0.0);
    std::vector<std::size_t> parts(weights.size());
    std::vector<std::pair<double, std::size_t>> remainders;
    std::size_t given = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        double exact = double(total) * double(weights[i]) / double(sum);
        parts[i] = std::size_t(exact);
        given += parts[i];
        remainders.push_back({-(exact - double(parts[i])), i});
    }
    std::sort(remainders.begin(), remainders.end());
    for (std::size_t k = 0; given < total && k < remainders.size(); ++k, ++given)
        ++parts[remainders[k].second];
    return parts;
}

// The groups' positions and triangles as one primitive (no material).
Primitive positions_only(const std::vector<Primitive>& groups) {
    Primitive one;
    for (const Primitive& group : groups) {
        const auto base = std::uint32_t(one.positions.size());
        one.positions.insert(one.positions.end(), group.positions.begin(), group.positions.end());
        for (std::uint32_t index : group.indices) one.indices.push_back(base + index);
    }
    one.polygon_count = one.triangle_count();
    return one;
}

}  // namespace

std::vector<Primitive> simplify_subtree(const Model& model, int root, std::size_t target_faces,
                                        const SimplifyOptions& options) {
    if (model.is_lod)
        throw_input_error(model.source, "simplify", "an LoD that boxlod exported cannot be simplified again");
    if (target_faces == 0) throw_input_error(model.source, "simplify", "the face target must be at least 1");
    std::vector<Primitive> groups = merge_primitives(model, subtree_nodes(model, root));
    if (groups.empty()) throw_input_error(model.source, "simplify", "the model has no triangles");
    if (options.geometry_only) groups = {positions_only(groups)};

    std::vector<Primitive> welded(groups.size());
    std::vector<char> flat(groups.size());  // char: written in parallel
    parallel_for(groups.size(), options.threads, [&](std::size_t g) {
        weld(welded[g] = std::move(groups[g]));
        flat[g] = !maps_normals(model, welded[g].material) && faceted(welded[g]);
    });
    std::vector<std::size_t> triangles;
    std::vector<double> weights;  // each material's share of the budget
    for (const Primitive& mesh : welded) {
        triangles.push_back(mesh.triangle_count());
        weights.push_back(options.budget_by_area ? surface_area(mesh) : double(mesh.triangle_count()));
    }
    const std::size_t target =
        std::min(target_faces, std::accumulate(triangles.begin(), triangles.end(), std::size_t(0)));

    // Each round gives the faces still missing (materials that came out below
    // their share: too small to simplify, or clustered away) to the materials
    // that can grow, in proportion to their size; a material's result is
    // replaced only by a larger one, so the total only grows, never past the
    // target. A material that did not grow is left alone from then on.
    std::vector<std::size_t> achieved(groups.size(), 0), budget = proportional_budget(target, weights);
    std::vector<char> done(groups.size(), false), stuck(groups.size(), false);  // char: written in parallel
    for (int round = 0; round < 8; ++round) {
        parallel_for(groups.size(), options.threads, [&](std::size_t g) {
            if (done[g] || (round > 0 && budget[g] == achieved[g])) return;
            Primitive mesh = simplify_mesh(welded[g], flat[g], budget[g], options);
            if (round == 0 || mesh.triangle_count() > achieved[g]) {
                groups[g] = std::move(mesh);
                achieved[g] = groups[g].triangle_count();
            } else
                stuck[g] = true;
        });
        std::size_t sum = std::accumulate(achieved.begin(), achieved.end(), std::size_t(0));
        if (!clusters(options) || sum >= target || double(target - sum) < 0.01 * double(target)) break;
        std::vector<double> growable(groups.size(), 0);
        for (std::size_t g = 0; g < groups.size(); ++g) {
            done[g] = achieved[g] == triangles[g] || stuck[g];
            if (!done[g]) growable[g] = weights[g];
        }
        if (std::accumulate(growable.begin(), growable.end(), 0.0) == 0) break;
        budget = proportional_budget(target - sum, growable);
        for (std::size_t g = 0; g < groups.size(); ++g) budget[g] += achieved[g];
    }

    std::vector<Primitive> simplified;
    for (Primitive& group : groups)
        if (!group.indices.empty()) simplified.push_back(std::move(group));  // else its share came to nothing
    return simplified;
}

Model simplify_model(const Model& model, std::size_t target_faces, const SimplifyOptions& options) {
    return model_of_primitives(model, simplify_subtree(model, 0, target_faces, options),
                               model.nodes.empty() ? "simplified" : model.nodes[0].name);
}

std::vector<SimplifyVariant> simplify_variants(int threads) {
    SimplifyOptions collapse, lock_border, sloppy, by_area;
    lock_border.lock_border = true;
    sloppy.edge_collapse = false;
    by_area.budget_by_area = true;
    std::vector<SimplifyVariant> variants = {
        {"collapse", collapse}, {"lock-border", lock_border}, {"sloppy", sloppy}, {"by-area", by_area}};
    for (SimplifyVariant& v : variants) v.options.threads = threads;
    return variants;
}

}  // namespace boxlod
