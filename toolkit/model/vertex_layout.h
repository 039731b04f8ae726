// The vertex attributes and index width boxlod's glTF export writes for a
// primitive, and so what its mesh costs (docs/design.md: Cost): only what its
// material samples, the smallest index type that holds its vertices.
#pragma once
#include "toolkit/model/model.h"

#include <compare>
#include <cstdint>
#include <vector>

namespace boxlod {

struct VertexLayout {
    bool normals = false;   // where the primitive has them (none: flat shading)
    bool uvs = false;       // where it has them and its material samples a texture
    bool tangents = false;  // where it has them and its material has a normal or height map
    int index_bytes = 4;    // 2 where every index fits below 65535 (glTF 2.0, Meshes: an index may not be the
                            // type's largest value)

    std::uint64_t vertex_bytes() const {
        return 12 + (normals ? 12 : 0) + (uvs ? 8 : 0) + (tangents ? 16 : 0);
    }
};

// Whether model.materials[material] (if any) has a normal or height map: its
// parts need their normals and tangent frames.
bool maps_normals(const Model& model, int material);

VertexLayout vertex_layout(const Primitive& primitive, const Model& model);

// What one draw call draws: the primitives of one material with the same
// attributes present, merged into one mesh (lod/hybrid/draw_calls.h), so a
// level counts one draw call per key (docs/cost.md: Draw calls).
struct DrawCallKey {
    int material = -1;
    bool normals = false, uvs = false, tangents = false;
    auto operator<=>(const DrawCallKey&) const = default;
};
DrawCallKey draw_call_key(const Primitive& primitive);

// Vertex + index bytes of one primitive as the glTF export writes it.
std::uint64_t primitive_mesh_bytes(const Primitive& primitive, const Model& model);
std::uint64_t mesh_bytes(const std::vector<Primitive>& primitives, const Model& model);  // summed

}  // namespace boxlod
