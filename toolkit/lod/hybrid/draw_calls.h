// Levels as engines load them (docs/cost.md: Draw calls): one node per
// material, the geometry of every part drawn with it merged into one welded
// mesh, instead of a node per kept part and box (tens of thousands in a city
// block, which Blender and engines import as as many objects).
#pragma once
#include "toolkit/model/model.h"

#include <string>
#include <vector>

namespace boxlod {

// The primitives of `nodes` merged, one per material and attribute set
// (normals, uvs, tangents present or not), in the order their first primitive
// appears; polygon counts add up. Not welded.
std::vector<Primitive> merge_primitives(const Model& model, const std::vector<int>& nodes);

// Vertices equal in every attribute become one, so edges are shared.
void weld(Primitive& primitive);

// Keeps the vertices `remap` maps to `unique` new ones (meshoptimizer's
// remap tables) and renumbers the indices.
void remap_vertices(Primitive& primitive, const std::vector<unsigned>& remap, std::size_t unique);

// `source`'s materials, textures, file and LoD mark with a root named
// `root_name` whose children, one per material and named after it, hold `primitives`.
Model model_of_primitives(const Model& source, std::vector<Primitive> primitives,
                          const std::string& root_name);

// The model with one node per material: equal materials merged first
// (toolkit/model/material_merge.h), then every primitive of a material merged and
// welded. Draws the same triangles.
Model merge_draw_calls(Model model, const std::string& root_name);

}  // namespace boxlod
