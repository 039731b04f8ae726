#include "toolkit/lod/pages/boxes.h"

#include "test_support.h"
#include "toolkit/cgal/box_fit.h"
#include "toolkit/formats/model_io.h"

#include "box_checks.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

namespace boxlod {
namespace {

using test::bitwise_equal;
using test::encloses;
using test::valid_frame;

OrientedBox make_box(Eigen::Vector3f center, float angle, Eigen::Vector3f half_extents) {
    OrientedBox box;
    box.center = center;
    box.axes = Eigen::AngleAxisf(angle, Eigen::Vector3f(1, 2, 3).normalized()).toRotationMatrix();
    box.half_extents = half_extents;
    return box;
}

// A closed box mesh (8 corners, 12 triangles) as a node's geometry.
void add_box_geometry(Node& node, const OrientedBox& box) {
    Primitive& primitive = node.primitives.emplace_back();
    auto corners = box_corners(box);
    primitive.positions.assign(corners.begin(), corners.end());
    primitive.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                         2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    primitive.polygon_count = 6;
}

std::vector<Eigen::Vector3f> subtree_vertices(const Model& model, int root) {
    std::vector<Eigen::Vector3f> out;
    for (const Primitive& primitive : model.nodes[root].primitives)
        out.insert(out.end(), primitive.positions.begin(), primitive.positions.end());
    for (int child : model.nodes[root].children) {
        auto more = subtree_vertices(model, child);
        out.insert(out.end(), more.begin(), more.end());
    }
    return out;
}

// root (scope) -> wall (scope smaller than its rotated box geometry: a sill
// sticks out), empty (no geometry), group (no scope) -> window (geometry,
// no scope), flat (one triangle, flat scope).
struct Scene {
    Model model;
    int root, wall, empty, group, window, flat;
};
Scene scene() {
    Scene s;
    Model& m = s.model;
    s.root = add_node(m, -1, "root");
    s.wall = add_node(m, s.root, "wall");
    s.empty = add_node(m, s.root, "empty");
    s.group = add_node(m, s.root, "group");
    s.window = add_node(m, s.group, "window");
    s.flat = add_node(m, s.root, "flat");
    OrientedBox wall = make_box({0, 0, 0}, 0.4f, {3, 2, 0.2f});
    add_box_geometry(m.nodes[s.wall], wall);
    add_box_geometry(m.nodes[s.wall],
                     make_box(wall.axes * Eigen::Vector3f(0, -1.9f, 0.3f), 0.4f, {1, 0.1f, 0.3f}));  // sill
    OrientedBox wall_scope = wall;
    wall_scope.half_extents = {2.5f, 1.5f, 0.2f};
    m.nodes[s.wall].scope = wall_scope;
    add_box_geometry(m.nodes[s.window], make_box({4, 1, 2}, 1.1f, {0.5f, 0.7f, 0.1f}));
    Primitive& triangle = m.nodes[s.flat].primitives.emplace_back();
    triangle.positions = {{5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
    triangle.indices = {0, 1, 2};
    triangle.polygon_count = 1;
    OrientedBox flat_scope;
    flat_scope.center = {5.5f, 0.5f, 0};
    flat_scope.half_extents = {0.5f, 0.5f, 0};
    m.nodes[s.flat].scope = flat_scope;
    OrientedBox root_scope;
    root_scope.half_extents = {6, 6, 6};
    m.nodes[s.root].scope = root_scope;
    return s;
}

TEST(Boxes, NamesRoundTrip) {
    for (BoxKind kind : {BoxKind::scope, BoxKind::expanded, BoxKind::minimal}) {
        BoxKind parsed{};
        ASSERT_TRUE(parse_box_kind(box_kind_name(kind), parsed));
        EXPECT_EQ(parsed, kind);
    }
    BoxKind kind{};
    EXPECT_FALSE(parse_box_kind("sphere", kind));
    EXPECT_STREQ(box_kind_name(BoxKind::expanded), "expanded");
}

TEST(Boxes, Measures) {
    OrientedBox box = make_box({1, 1, 1}, 0.3f, {1, 2, 3});
    EXPECT_FLOAT_EQ(box_volume(box), 48);
    EXPECT_FLOAT_EQ(box_area(box), 88);
    EXPECT_FLOAT_EQ(box_diagonal(box), 2 * std::sqrt(14.f));
    EXPECT_FLOAT_EQ(box_max_extent(box), 6);
}

TEST(Boxes, EveryKindEnclosesOrKeepsTheScope) {
    Scene s = scene();
    for (BoxKind kind : {BoxKind::scope, BoxKind::expanded, BoxKind::minimal}) {
        auto boxes = node_boxes(s.model, kind, 1);
        ASSERT_EQ(boxes.size(), s.model.nodes.size());
        EXPECT_FALSE(boxes[s.empty]) << box_kind_name(kind);
        for (int node : {s.root, s.wall, s.group, s.window, s.flat}) {
            ASSERT_TRUE(boxes[node]) << box_kind_name(kind) << " node " << node;
            EXPECT_TRUE(valid_frame(*boxes[node]));
            EXPECT_GT(boxes[node]->half_extents.minCoeff(), 0);
            EXPECT_TRUE(boxes[node]->center.allFinite());
            // The scope kind keeps a scope that is too small; everything else encloses.
            bool keeps_scope = kind == BoxKind::scope && s.model.nodes[node].scope;
            if (keeps_scope) continue;
            for (const Eigen::Vector3f& p : subtree_vertices(s.model, node))
                EXPECT_TRUE(encloses(*boxes[node], p)) << box_kind_name(kind) << " node " << node;
        }
    }
}

TEST(Boxes, ScopeIsTheStoredScope) {
    Scene s = scene();
    auto boxes = node_boxes(s.model, BoxKind::scope, 1);
    const Scope& scope = *s.model.nodes[s.wall].scope;
    EXPECT_EQ(boxes[s.wall]->center, scope.center);
    EXPECT_EQ(boxes[s.wall]->axes, scope.axes);
    EXPECT_EQ(boxes[s.wall]->half_extents, scope.half_extents);
    // The flat scope gets a small thickness (1e-4 of the model's size) instead of zero.
    EXPECT_GT(boxes[s.flat]->half_extents.z(), 0);
    EXPECT_LT(boxes[s.flat]->half_extents.z(), 1e-2f);
}

TEST(Boxes, ExpandedGrowsTheScopeJustEnough) {
    Scene s = scene();
    auto boxes = node_boxes(s.model, BoxKind::expanded, 1);
    const OrientedBox& expanded = *boxes[s.wall];
    const Scope& scope = *s.model.nodes[s.wall].scope;
    EXPECT_TRUE(expanded.axes.isApprox(scope.axes, 1e-6f));
    for (const Eigen::Vector3f& corner : box_corners(scope)) EXPECT_TRUE(encloses(expanded, corner));
    // The wall geometry is 3 x 2 (half), the sill reaches 0.6 in front: the wall's own box, grown in +z only.
    EXPECT_NEAR(expanded.half_extents.x(), 3, 1e-5);
    EXPECT_NEAR(expanded.half_extents.y(), 2, 1e-5);
    EXPECT_NEAR(expanded.half_extents.z(), 0.4f, 1e-5);
    Eigen::Vector3f shift = scope.axes.transpose() * (expanded.center - scope.center);
    EXPECT_TRUE(shift.isApprox(Eigen::Vector3f(0, 0, 0.2f), 1e-5f)) << shift.transpose();
    // The root's scope already encloses everything: unchanged.
    EXPECT_TRUE(boxes[s.root]->half_extents.isApprox(Eigen::Vector3f(6, 6, 6), 1e-6f));
    EXPECT_TRUE(boxes[s.root]->center.isZero(1e-6f));
}

TEST(Boxes, NodesWithoutScopeUseTheMinimalBox) {
    Scene s = scene();
    auto minimal = node_boxes(s.model, BoxKind::minimal, 1);
    for (BoxKind kind : {BoxKind::scope, BoxKind::expanded}) {
        auto boxes = node_boxes(s.model, kind, 1);
        EXPECT_TRUE(bitwise_equal(boxes[s.group], minimal[s.group]));
        EXPECT_TRUE(bitwise_equal(boxes[s.window], minimal[s.window]));
    }
}

TEST(Boxes, MinimalIsNoLargerThanExpanded) {
    Scene s = scene();
    auto minimal = node_boxes(s.model, BoxKind::minimal, 1);
    auto expanded = node_boxes(s.model, BoxKind::expanded, 1);
    for (int node : {s.root, s.wall, s.window}) {
        EXPECT_LE(box_volume(*minimal[node]), box_volume(*expanded[node]) * (1 + 1e-4f)) << node;
    }
    EXPECT_LT(box_volume(*minimal[s.root]), 0.5f * box_volume(*expanded[s.root]));
}

TEST(Boxes, IdenticalHullsAreSolvedOnce) {
    // The group's only geometry is the window's: one computation, the same bits.
    Scene s = scene();
    MinimalBoxCounts counts;
    auto boxes = node_boxes(s.model, BoxKind::minimal, 2, counts);
    EXPECT_TRUE(bitwise_equal(boxes[s.group], boxes[s.window]));
    EXPECT_EQ(counts.nodes, 5u);  // root, wall, group, window, flat
    EXPECT_EQ(counts.reused, 1u);
    EXPECT_EQ(counts.computed, 4u);
}

TEST(Boxes, TranslatedCopiesAreSolvedOnce) {
    // Three windows, equal up to an exact translation (axis-aligned, dyadic), under one facade node.
    Model model;
    int facade = add_node(model, -1, "facade");
    std::vector<int> windows;
    for (float x : {0.f, 4.f, 8.f}) {
        windows.push_back(add_node(model, facade, "window"));
        add_box_geometry(model.nodes[windows.back()], make_box({x, 1, 0}, 0, {0.5f, 0.75f, 0.125f}));
    }
    MinimalBoxCounts counts;
    auto boxes = node_boxes(model, BoxKind::minimal, 1, counts);
    EXPECT_EQ(counts.nodes, 4u);
    EXPECT_EQ(counts.computed, 2u);  // the facade, one window
    EXPECT_EQ(counts.reused, 2u);
    for (int window : windows) {
        for (const Eigen::Vector3f& p : subtree_vertices(model, window))
            EXPECT_TRUE(encloses(*boxes[window], p));
        EXPECT_NEAR(box_volume(*boxes[window]), 8 * 0.5f * 0.75f * 0.125f, 1e-4);
    }
}

TEST(Boxes, SameBitsForAnyThreadCount) {
    Scene s = scene();
    // More nodes than threads, with distinct hulls, so the work really is shared out.
    for (int i = 0; i < 8; ++i) {
        int node = add_node(s.model, s.root, "extra");
        add_box_geometry(s.model.nodes[node],
                         make_box({float(i), 2, -1}, 0.2f * i, {0.3f, 0.2f + 0.1f * i, 0.4f}));
    }
    for (BoxKind kind : {BoxKind::scope, BoxKind::expanded, BoxKind::minimal}) {
        auto one = node_boxes(s.model, kind, 1);
        for (int threads : {2, 3}) {
            auto many = node_boxes(s.model, kind, threads);
            for (std::size_t i = 0; i < one.size(); ++i)
                EXPECT_TRUE(bitwise_equal(one[i], many[i])) << box_kind_name(kind) << " node " << i;
        }
    }
}

TEST(Boxes, FzkHausEveryNodeWithGeometryGetsAnEnclosingBox) {
    Model model = load_model(test::fzk_haus_ifc);
    auto boxes = node_boxes(model, BoxKind::minimal, 0);
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        std::vector<Eigen::Vector3f> vertices = subtree_vertices(model, int(i));
        ASSERT_EQ(bool(boxes[i]), !vertices.empty()) << "node " << i;
        if (!boxes[i]) continue;
        EXPECT_TRUE(valid_frame(*boxes[i]));
        EXPECT_GT(boxes[i]->half_extents.minCoeff(), 0);
        for (const Eigen::Vector3f& p : vertices) ASSERT_TRUE(encloses(*boxes[i], p)) << "node " << i;
    }
}

}  // namespace
}  // namespace boxlod
