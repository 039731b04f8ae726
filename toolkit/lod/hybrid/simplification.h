// Quadric edge-collapse mesh simplification (Garland-Heckbert, the lecture
// notes' method) with meshoptimizer, keeping materials and texture
// coordinates: the classic baseline (docs/sweeps.md: baselines) and the
// simplified sub-trees among the hybrid level mode's candidates (hybrid.h).
#pragma once
#include "toolkit/model/model.h"

#include <cstddef>
#include <vector>

namespace boxlod {

struct SimplifyOptions {
    bool edge_collapse = true;  // false: vertex clustering alone (meshopt_simplifySloppy)
    bool lock_border = false;   // never move vertices on open borders (meshopt_SimplifyLockBorder)
    // Edge collapse keeps topology, so it stalls on many small separate parts
    // (panes, tiles, sills); vertex clustering (meshopt_simplifySloppy) then
    // takes what is left to the budget. Off: pure edge collapse, which may
    // stay above it.
    bool clustering_fallback = true;
    // The budget is split over the materials in proportion to their triangles,
    // or with this to their surface area: large walls of few triangles then keep
    // them while dense small parts (furniture, fittings) give theirs up.
    bool budget_by_area = false;
    // Every primitive as one mesh of positions alone (materials, normals and
    // uvs dropped), simplified across material seams: a baked proxy takes its
    // colours and normals from its bake (baked_proxy.h), not from its materials.
    bool geometry_only = false;
    int threads = 0;  // 0 = all cores; the result never depends on it
};

// The model with about `target_faces` triangles (the result's faces are its
// triangles). Geometry is merged into one node per material under a new root:
// the simplifier may then collapse across the original parts (adjacent tiles
// share welded vertices) and no part keeps a floor of its own triangles; the
// LoD comparison needs faces and images only, not the hierarchy. The budget is
// split over the materials in proportion to their triangle counts (or areas). Vertices
// equal in position, normal, uv and tangent are welded first, so uv and normal
// seams stay seams (vertices on them only move along them).
// Faces a material cannot use (parts too small to simplify, or clustered
// away: such a material may vanish at small budgets) go to the others in up
// to seven more rounds, so the total ends close to, and never above, the
// target. Materials and textures are kept as they are. A faceted part (a
// position with two normals: flat-shaded) comes out without normals, drawn
// flat-shaded: meshoptimizer 0.18 leaves it one normal per kept position;
// only a material with a normal or height map keeps them, and tangents. A
// target at or above the triangle count keeps every triangle. Deterministic.
// Throws InputError for target_faces 0, an LoD model or a model without triangles.
Model simplify_model(const Model& model, std::size_t target_faces, const SimplifyOptions& options);
// The same for the sub-tree under `root` alone (the hybrid level mode's
// candidates): its primitives merged and simplified, one per material and
// attribute set, with the model's material indices.
std::vector<Primitive> simplify_subtree(const Model& model, int root, std::size_t target_faces,
                                        const SimplifyOptions& options);

// What meshoptimizer 0.18 (Debian 12) offers for a face budget, as named
// variants: `collapse` (edge collapse, then clustering: boxlod simplify's
// default), `lock-border` (the same with open borders locked), `sloppy`
// (vertex clustering alone) and `by-area` (collapse with the budget split by
// surface area). The sweep's simplification-best baseline keeps the
// one with the lowest image error at each budget (docs/sweeps.md). 0.18 has
// no attribute-aware simplification (meshopt_simplifyWithAttributes came in 0.20).
struct SimplifyVariant {
    const char* name;
    SimplifyOptions options;
};
std::vector<SimplifyVariant> simplify_variants(int threads);

}  // namespace boxlod
