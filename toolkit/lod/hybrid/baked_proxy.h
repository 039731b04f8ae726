// A baked proxy (docs/design.md: The hybrid level mode): a sub-tree's
// simplified mesh drawn with the colours and normals its box's faces baked,
// the far-level proxy that Simplygon and Unreal's HLOD ship. Its charts are
// the box's faces: each triangle samples the face that sees it, so the
// proxy needs no parametrization of its own and shares the box's pages.
// The simplified mesh gives the silhouette a box cannot (a curved or pitched
// roof); the pages give the detail simplification drops (windows, tiles).
#pragma once
#include "toolkit/lod/pages/bake.h"
#include "toolkit/model/model.h"

#include <array>
#include <cstdint>
#include <vector>

namespace boxlod {

// Which face of the box a triangle samples: of the faces it looks towards,
// the one whose baked surface lies where the triangle does (within a few
// texels or a tenth of the box's depth there), most squarely facing it;
// where none does (the triangle is hidden from every side it faces), the one
// whose baked surface lies nearest. Faces that saw nothing are never chosen,
// and a triangle facing only such faces is dropped.
int sampled_face(const std::array<OrientedBoxFace, 6>& faces, const std::array<const BakedFace*, 6>& baked,
                 const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c);

std::array<const BakedFace*, 6> face_pointers(const std::array<BakedFace, 6>& baked);

// Per box face, the triangles of `simplified` that sample it: positions as
// simplified; normals and tangents the face's frame, in which its normal map
// was baked, so the proxy shades with the original's normals; uvs over the
// whole face, 0..1 right and down as bake_face's image. Faces no triangle
// samples are empty. Primitives' materials are left at -1 for the caller.
std::array<Primitive, 6> baked_proxy_faces(const std::vector<Primitive>& simplified, const OrientedBox& box,
                                           const std::array<const BakedFace*, 6>& baked);

// Its mesh as the export writes it: position, normal, uv and tangent per vertex, and the indices.
std::uint64_t baked_proxy_mesh_bytes(const std::array<Primitive, 6>& faces);

}  // namespace boxlod
