// CGAL's quadric edge collapse as a baseline (docs/sweeps.md: cgal): the
// Garland-Heckbert plane policies of CGAL's Surface_mesh_simplification (5.5
// in Debian 12) on each material's mesh welded by position. CGAL keeps no
// vertex attributes, so a surviving vertex keeps the uv and tangent it had
// (seams merge) and every triangle gets its flat normal.
#pragma once
#include "toolkit/model/model.h"

#include <cstddef>

namespace boxlod {

// The model with at most about `target_faces` triangles, one node per material
// under a new root, the budget split over the materials by surface area (as
// simplify_model's by-area variant). Edge collapse stops where the mesh
// allows no more (separate parts stay), so a material may end above its
// share. Deterministic. Throws InputError for target_faces 0, an LoD model or a
// model without triangles.
Model cgal_simplify(const Model& model, std::size_t target_faces);

}  // namespace boxlod
