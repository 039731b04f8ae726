// Sub-trees that keep their geometry where their level values would box them
// (cut.h). Both rules go beyond the manual, whose cut boxes every sub-tree below
// the current level however little it holds.
// - small (`keep_small_subtrees`): at most 6 faces, its box's own count, so no
//   level draws more faces than the original.
// - cheaper (`keep_cheaper_subtrees`, docs/cost.md: Boxes that pay their way): the
//   sub-tree's mesh costs fewer bytes than its box would, so no box costs more
//   than the geometry it replaces, and no level more than the original or the
//   manual's cut at that level. A box's bytes are estimated before baking
//   (box_bytes_estimate), its faces whole as sized, never smaller than cropped.
// A node is kept with its whole sub-tree: boxing the children of a node too
// cheap to box could cost more than its own box.
#pragma once
#include "toolkit/lod/pages/bake.h"
#include "toolkit/lod/pages/texture_sizing.h"
#include "toolkit/model/model.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace boxlod {

// Faces (polygons as stored) and triangles of each node's whole sub-tree.
std::vector<std::size_t> subtree_faces(const Model& model);
std::vector<std::size_t> subtree_triangles(const Model& model);
// Vertex and index bytes of each node's whole sub-tree as exported (cost.h).
std::vector<std::uint64_t> subtree_mesh_bytes(const Model& model);

// What a box costs an engine: its 6 quads' mesh (uvs and tangents when
// `textured`) and, when textured, each face's texels as sized with a gutter of
// sizing.gutter on each side, at 2 bytes per texel (BC1 colour, BC5 normal and
// BC4 height: 8 + 16 + 8 bytes per 4 x 4 block) times 4/3 for the mip chain.
std::uint64_t box_bytes_estimate(const OrientedBox& box, const TextureSizing& sizing, bool textured);
// Its parts: a face's texels as sized with the gutter on each side, and what
// texels cost in pages (2 bytes each, 4/3 for the mip chain).
std::uint64_t face_page_texels(const OrientedBoxFace& face, const TextureSizing& sizing);
std::uint64_t page_bytes(std::uint64_t texels);

struct KeptSubtrees {
    bool small = false;    // at most 6 faces
    bool cheaper = false;  // a mesh cheaper than its box
};
// For each node: whether it keeps its geometry (every descendant of a kept node is kept) (`boxes` as
// node_boxes gives them).
std::vector<bool> kept_subtrees(const Model& model, const std::vector<std::optional<OrientedBox>>& boxes,
                                KeptSubtrees rules, const TextureSizing& sizing, bool textured);

}  // namespace boxlod
