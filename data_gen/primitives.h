// Built-in geometry that `i(...)` inserts, made to fill a scope: box, quad,
// cylinder, gable roof, hip roof. Every polygon is counted once in
// `polygon_count` (a box has 6, a quad 1) and carries a normal and a tangent.
#pragma once
#include "data_gen/scope_box.h"
#include "toolkit/model/model.h"

#include <array>
#include <string>

namespace boxlod {

// One face of a scope's box, in the scope's own frame (the grammar's side of
// a box; the LoD builder's is OrientedBoxFace): `u` runs to the right and `v`
// up as seen from outside, u x v is the outward normal.
struct ScopeFace {
    const char* name;  // front (+z), right (+x), back (-z), left (-x), top (+y), bottom (-y)
    Eigen::Vector3f origin, u, v;
    float width = 0, height = 0;
};

// The six faces in the order front, right, back, left, top, bottom. The
// component split and the box primitive both use them.
std::array<ScopeFace, 6> scope_faces(const Eigen::Vector3f& size);

bool is_builtin_primitive(const std::string& name);
std::string builtin_primitive_names();  // "box, quad, cylinder, gable, hip"

// `name` filling a scope of `size`, in the scope's own metres (origin at its
// corner). The quad is the scope's front rectangle (z = size.z); the cylinder
// and the roofs stand on y = 0 and rise along y; a gable roof's ridge runs
// along x, a hip roof's along the longer horizontal side. `segments` is the
// cylinder's number of sides. Faces of zero area are left out.
Primitive builtin_primitive(const std::string& name, const Eigen::Vector3f& size, int segments = 12);

// Appends a convex polygon (a fan of triangles) counted as one polygon; its
// normal comes from the points' winding (counter-clockwise seen from outside)
// unless `vertex_normals` are given; its tangent runs along the first edge.
// Degenerate polygons are skipped.
void add_polygon(Primitive& primitive, const std::vector<Eigen::Vector3f>& points,
                 const std::vector<Eigen::Vector3f>& vertex_normals = {});

// Moves a primitive built in `scope`'s own metres into world space.
void place_in_world(Primitive& primitive, const ScopeBox& scope);

// Texture coordinates from world positions: metres along the tangent and
// down the bitangent, divided by `tile_metres`, so the pieces of one wall
// continue each other's texture.
void planar_texture_coordinates(Primitive& primitive, float tile_metres);

}  // namespace boxlod
