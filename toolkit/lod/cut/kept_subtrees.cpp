#include "toolkit/lod/cut/kept_subtrees.h"

#include "toolkit/lod/pages/bake.h"
#include "toolkit/model/cost.h"

namespace boxlod {
namespace {

// Sums a per-node value over each node's sub-tree.
template <typename T, typename OwnValue>
std::vector<T> sum_over_subtrees(const Model& model, OwnValue own_value) {
    std::vector<T> sums(model.nodes.size(), T(0));
    // A parent comes before its children (model.h), so going backwards a node is complete before its parent
    // adds it.
    for (std::size_t n = model.nodes.size(); n-- > 0;) {
        for (const Primitive& primitive : model.nodes[n].primitives) sums[n] += own_value(primitive);
        if (model.nodes[n].parent >= 0) sums[std::size_t(model.nodes[n].parent)] += sums[n];
    }
    return sums;
}

}  // namespace

std::vector<std::size_t> subtree_faces(const Model& model) {
    return sum_over_subtrees<std::size_t>(model, [](const Primitive& p) { return p.polygon_count; });
}

std::vector<std::size_t> subtree_triangles(const Model& model) {
    return sum_over_subtrees<std::size_t>(model, [](const Primitive& p) { return p.triangle_count(); });
}

std::vector<std::uint64_t> subtree_mesh_bytes(const Model& model) {
    return sum_over_subtrees<std::uint64_t>(
        model, [&](const Primitive& p) { return primitive_mesh_bytes(p, model); });
}

std::uint64_t box_bytes_estimate(const OrientedBox& box, const TextureSizing& sizing, bool textured) {
    // Per quad 4 vertices (position, normal; uv, tangent when textured) and 6 16-bit indices, as the export
    // writes them.
    const std::uint64_t vertex_bytes = VertexLayout{true, textured, textured, 2}.vertex_bytes();
    std::uint64_t bytes = 6 * (4 * vertex_bytes + 6 * 2);
    if (!textured) return bytes;
    std::uint64_t texels = 0;
    for (const OrientedBoxFace& face : oriented_box_faces(box)) texels += face_page_texels(face, sizing);
    return bytes + page_bytes(texels);
}

std::uint64_t face_page_texels(const OrientedBoxFace& face, const TextureSizing& sizing) {
    const Eigen::Vector2i size = face_texels(2 * face.half_width, 2 * face.half_height, sizing);
    return std::uint64_t(size.x() + 2 * sizing.gutter) * std::uint64_t(size.y() + 2 * sizing.gutter);
}

std::uint64_t page_bytes(std::uint64_t texels) { return texels * 2 * 4 / 3; }

std::vector<bool> kept_subtrees(const Model& model, const std::vector<std::optional<OrientedBox>>& boxes,
                                KeptSubtrees rules, const TextureSizing& sizing, bool textured) {
    constexpr std::size_t box_faces = 6;
    std::vector<bool> kept(model.nodes.size(), false);
    std::vector<std::size_t> faces;
    std::vector<std::uint64_t> mesh_bytes;
    if (rules.small) faces = subtree_faces(model);
    if (rules.cheaper) mesh_bytes = subtree_mesh_bytes(model);
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        if (rules.small && faces[n] <= box_faces) kept[n] = true;
        if (rules.cheaper && boxes[n] && mesh_bytes[n] <= box_bytes_estimate(*boxes[n], sizing, textured))
            kept[n] = true;
        // The whole sub-tree: boxing descendants of a node too cheap to box could cost more than its box
        // (a parent comes before its children, model.h).
        if (model.nodes[n].parent >= 0 && kept[std::size_t(model.nodes[n].parent)]) kept[n] = true;
    }
    return kept;
}

}  // namespace boxlod
