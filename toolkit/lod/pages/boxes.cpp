#include "toolkit/lod/pages/boxes.h"

#include "base/parallel.h"
#include "toolkit/cgal/box_fit.h"
#include "toolkit/cgal/minimal_box.h"

#include <Eigen/Dense>  // cross products, determinants

#include <algorithm>
#include <bit>
#include <cstdint>
#include <unordered_map>

namespace boxlod {

namespace {

constexpr EnumEntry<BoxKind> box_kind_table[] = {
    {BoxKind::scope, "scope", "the grammar's scope as stored (may be smaller than the geometry)"},
    {BoxKind::expanded, "expanded", "the scope's orientation, grown to enclose the sub-tree's geometry"},
    {BoxKind::minimal, "minimal", "CGAL's minimum-volume box of the sub-tree's vertices"},
};

// Whether each node's sub-tree has geometry; children follow their parents, so one backward pass.
std::vector<char> geometry_below(const Model& model) {
    std::vector<char> below(model.nodes.size(), 0);
    for (std::size_t i = model.nodes.size(); i-- > 0;) {
        const Node& node = model.nodes[i];
        below[i] = below[i] || node.has_geometry();
        if (below[i] && node.parent >= 0) below[node.parent] = 1;
    }
    return below;
}

void append_positions(const Node& node, std::vector<Eigen::Vector3f>& out) {
    for (const Primitive& primitive : node.primitives)
        out.insert(out.end(), primitive.positions.begin(), primitive.positions.end());
}

std::vector<Eigen::Vector3f> subtree_positions(const Model& model, int root) {
    std::vector<Eigen::Vector3f> out;
    std::vector<int> stack{root};
    while (!stack.empty()) {
        const Node& node = model.nodes[stack.back()];
        stack.pop_back();
        append_positions(node, out);
        stack.insert(stack.end(), node.children.begin(), node.children.end());
    }
    return out;
}

// FNV-1a (64 bit) over the shape's bit patterns, then the splitmix64
// finaliser (Steele, Lea & Flood 2014) to spread the bits: a content hash that
// is the same on every platform and run.
std::uint64_t hash_shape(const HullShape& shape) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](std::uint64_t word) {
        for (int byte = 0; byte < 8; ++byte) {
            h ^= (word >> (8 * byte)) & 0xff;
            h *= 1099511628211ull;
        }
    };
    for (const Eigen::Vector3d& p : shape.relative)
        for (int k = 0; k < 3; ++k) mix(std::bit_cast<std::uint64_t>(p[k]));
    mix(shape.flat);
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
}

// Each node's sub-tree hull vertices where `wanted` or an ancestor needs them,
// bottom-up one depth at a time (a node's hull is the hull of its own vertices
// and its children's hulls), each node writing only its own slot.
std::vector<std::vector<Eigen::Vector3f>> subtree_hulls(const Model& model, const std::vector<char>& wanted,
                                                        const std::vector<char>& below, int threads) {
    const std::size_t n = model.nodes.size();
    std::vector<char> needed(n, 0);
    std::vector<int> depth(n, 0);
    std::vector<std::vector<int>> by_depth(1);
    for (std::size_t i = 0; i < n; ++i) {
        int parent = model.nodes[i].parent;
        needed[i] = below[i] && (wanted[i] || (parent >= 0 && needed[parent]));
        depth[i] = parent >= 0 ? depth[parent] + 1 : 0;
        if (!needed[i]) continue;
        if (depth[i] >= int(by_depth.size())) by_depth.resize(depth[i] + 1);
        by_depth[depth[i]].push_back(int(i));
    }
    std::vector<std::vector<Eigen::Vector3f>> hulls(n);
    for (std::size_t d = by_depth.size(); d-- > 0;) {
        const std::vector<int>& nodes = by_depth[d];
        parallel_for(nodes.size(), threads, [&](std::size_t k) {
            const Node& node = model.nodes[nodes[k]];
            std::vector<Eigen::Vector3f> points;
            append_positions(node, points);
            for (int child : node.children)
                points.insert(points.end(), hulls[child].begin(), hulls[child].end());
            hulls[nodes[k]] = hull_vertices(points);
        });
    }
    return hulls;
}

// Minimal boxes for the `wanted` nodes. The orientation (the costly part) is
// solved once per distinct hull shape (equal up to translation), with a seed
// from the shape, so a shared orientation is exactly the one the node would
// get; each node then fits its own box around its own hull.
void minimal_boxes(const Model& model, const std::vector<char>& wanted, const std::vector<char>& below,
                   int threads, std::vector<std::optional<OrientedBox>>& boxes, MinimalBoxCounts& counts) {
    const std::size_t n = model.nodes.size();
    const std::vector<std::vector<Eigen::Vector3f>> hulls = subtree_hulls(model, wanted, below, threads);
    std::vector<HullShape> shapes(n);
    parallel_for(n, threads, [&](std::size_t i) {
        if (wanted[i]) shapes[i] = hull_shape(hulls[i]);
    });
    std::unordered_map<std::uint64_t, std::vector<int>> by_hash;
    std::vector<std::uint64_t> seed(n, 0);
    std::vector<int> source(n, -1), jobs;
    for (std::size_t i = 0; i < n; ++i) {
        if (!wanted[i]) continue;
        ++counts.nodes;
        seed[i] = hash_shape(shapes[i]);
        std::vector<int>& same_hash = by_hash[seed[i]];
        auto same =
            std::find_if(same_hash.begin(), same_hash.end(), [&](int j) { return shapes[j] == shapes[i]; });
        if (same != same_hash.end()) {
            source[i] = *same;
            ++counts.reused;
            continue;
        }
        same_hash.push_back(int(i));
        source[i] = int(i);
        jobs.push_back(int(i));
    }
    counts.computed += jobs.size();
    std::vector<Eigen::Matrix3d> axes(n);
    parallel_for(jobs.size(), threads,
                 [&](std::size_t k) { axes[jobs[k]] = minimal_box_axes(shapes[jobs[k]], seed[jobs[k]]); });
    parallel_for(n, threads, [&](std::size_t i) {
        if (wanted[i]) boxes[i] = fit_minimal_box(axes[source[i]], hulls[i]);
    });
}

// The scope as stored, with a valid frame: a left-handed one has its third axis
// negated (the same box); one that is not orthonormal is re-orthonormalised.
OrientedBox scope_box(const Scope& scope) {
    OrientedBox box = scope;
    box.half_extents = scope.half_extents.cwiseAbs();
    if (box.axes.determinant() < 0) box.axes.col(2) = -box.axes.col(2);
    if (!(box.axes.transpose() * box.axes).isApprox(Eigen::Matrix3f::Identity(), 1e-5f))
        box.axes = orthonormal_frame(box.axes.cast<double>()).cast<float>();
    return box;
}

// The scope's frame, grown (in each direction separately, so the centre may
// move) just enough to enclose the sub-tree's vertices.
OrientedBox expanded_box(const Model& model, int node, const OrientedBox& scope) {
    std::vector<Eigen::Vector3f> points = subtree_positions(model, node);
    for (const Eigen::Vector3f& corner : box_corners(scope)) points.push_back(corner);
    return fit_box(scope.axes.cast<double>(), points);
}

}  // namespace

std::span<const EnumEntry<BoxKind>> box_kinds() { return box_kind_table; }
bool parse_box_kind(const std::string& name, BoxKind& kind) { return parse_enum(box_kinds(), name, kind); }
const char* box_kind_name(BoxKind kind) { return enum_name(box_kinds(), kind); }

std::vector<std::optional<OrientedBox>> node_boxes(const Model& model, BoxKind kind, int threads) {
    MinimalBoxCounts counts;
    return node_boxes(model, kind, threads, counts);
}

std::vector<std::optional<OrientedBox>> node_boxes(const Model& model, BoxKind kind, int threads,
                                                   MinimalBoxCounts& counts) {
    const std::size_t n = model.nodes.size();
    const std::vector<char> below = geometry_below(model);
    std::vector<char> wanted(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        wanted[i] = below[i] && (kind == BoxKind::minimal || !model.nodes[i].scope);
    std::vector<std::optional<OrientedBox>> boxes(n);
    minimal_boxes(model, wanted, below, threads, boxes, counts);
    // Flat scopes (a facade) and flat geometry still get a thickness, relative to the model's size.
    const float thickness = std::max(1e-6f, 1e-4f * model_bounds(model).size().maxCoeff());
    parallel_for(n, threads, [&](std::size_t i) {
        if (!below[i]) return;
        if (!wanted[i]) {
            OrientedBox scope = scope_box(*model.nodes[i].scope);
            boxes[i] = kind == BoxKind::scope ? scope : expanded_box(model, int(i), scope);
        }
        boxes[i] = with_min_thickness(*boxes[i], thickness);
    });
    return boxes;
}

float box_volume(const OrientedBox& box) { return 8 * box.half_extents.prod(); }

float box_area(const OrientedBox& box) {
    const Eigen::Vector3f& h = box.half_extents;
    return 8 * (h.x() * h.y() + h.y() * h.z() + h.z() * h.x());
}

float box_diagonal(const OrientedBox& box) { return 2 * box.half_extents.norm(); }

float box_max_extent(const OrientedBox& box) { return 2 * box.half_extents.maxCoeff(); }

}  // namespace boxlod
