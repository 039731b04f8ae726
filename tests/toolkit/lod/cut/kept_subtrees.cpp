#include "toolkit/lod/cut/kept_subtrees.h"

#include "toolkit/lod/cut/cut.h"
#include "toolkit/model/cost.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {
// root -> a -> a1 (geometry), a2 (geometry); root -> b (geometry)
Model tree(std::size_t a1_faces, std::size_t a2_faces, std::size_t b_faces) {
    Model model;
    add_node(model, -1, "root");
    int a = add_node(model, 0, "a");
    add_node(model, a, "a1");
    add_node(model, a, "a2");
    add_node(model, 0, "b");
    const std::size_t faces[] = {a1_faces, a2_faces, b_faces};
    for (int n : {2, 3, 4}) {
        Primitive p;
        const std::size_t count = faces[n - 2];
        for (std::size_t i = 0; i < count; ++i) {
            auto base = std::uint32_t(p.positions.size());
            p.positions.insert(p.positions.end(), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
            p.normals.insert(p.normals.end(), 3, Eigen::Vector3f::UnitZ());
            p.indices.insert(p.indices.end(), {base, base + 1, base + 2});
        }
        p.polygon_count = count;
        model.nodes[std::size_t(n)].primitives.push_back(p);
    }
    return model;
}
OrientedBox cube(float side) {
    OrientedBox box;
    box.half_extents = Eigen::Vector3f::Constant(side / 2);
    return box;
}
// A sizing whose pixel is 1 world unit: 2 d tan(45 / 2) / resolution = 1.
TextureSizing unit_pixel() {
    TextureSizing sizing;
    sizing.resolution = 100;
    sizing.distance = float(50 / std::tan(45 * M_PI / 360));
    return sizing;
}
}  // namespace

TEST(KeptSubtrees, SubtreeSumsAddEveryDescendant) {
    Model model = tree(7, 2, 3);
    EXPECT_EQ(subtree_faces(model), (std::vector<std::size_t>{12, 9, 7, 2, 3}));
    // Per triangle 3 vertices of position + normal (24 bytes) and 3 16-bit indices.
    const std::uint64_t triangle = 3 * 24 + 3 * 2;
    EXPECT_EQ(
        subtree_mesh_bytes(model),
        (std::vector<std::uint64_t>{12 * triangle, 9 * triangle, 7 * triangle, 2 * triangle, 3 * triangle}));
    EXPECT_EQ(subtree_mesh_bytes(model)[2], primitive_mesh_bytes(model.nodes[2].primitives[0], model));
}

TEST(KeptSubtrees, BoxBytesAreSixQuadsAndTheirGutteredTexelsAtTwoBytesWithMips) {
    TextureSizing sizing = unit_pixel();
    sizing.gutter = 2;
    // Untextured: 6 quads of 4 vertices x 24 bytes and 6 indices x 2 bytes.
    EXPECT_EQ(box_bytes_estimate(cube(10), sizing, false), 6u * (4 * 24 + 12));
    // Textured: vertices of 48 bytes; each face 10 x 10 texels, 14 x 14 with gutters.
    EXPECT_EQ(box_bytes_estimate(cube(10), sizing, true), 6u * (4 * 48 + 12) + 6u * 14 * 14 * 2 * 4 / 3);
    // Farther away a face needs fewer texels.
    TextureSizing far = sizing;
    far.distance *= 2;
    EXPECT_EQ(box_bytes_estimate(cube(10), far, true), 6u * (4 * 48 + 12) + 6u * 9 * 9 * 2 * 4 / 3);
}

TEST(KeptSubtrees, SmallSubtreesHaveAtMostABoxsFaces) {
    Model model = tree(7, 2, 3);
    std::vector<std::optional<OrientedBox>> boxes(model.nodes.size(), cube(1));
    EXPECT_EQ(kept_subtrees(model, boxes, {true, false}, unit_pixel(), true),
              (std::vector<bool>{false, false, false, true, true}));
    EXPECT_EQ(kept_subtrees(model, boxes, {false, false}, unit_pixel(), true), std::vector<bool>(5, false));
}

TEST(KeptSubtrees, CheaperSubtreesCostFewerBytesThanTheirBox) {
    // 100 triangles cost 7,800 bytes, 10 cost 780; a textured box of side 10 at one texel per unit 4,360.
    Model model = tree(100, 10, 10);
    const TextureSizing sizing = unit_pixel();
    std::vector<std::optional<OrientedBox>> boxes(model.nodes.size(), cube(10));
    ASSERT_EQ(box_bytes_estimate(cube(10), sizing, true), 1224u + 3136u);
    const std::vector<bool> kept = kept_subtrees(model, boxes, {false, true}, sizing, true);
    EXPECT_EQ(kept, (std::vector<bool>{false, false, false, true,
                                       true}));  // a1 (100) and a (110) pay; a2, b do not
    // The cut opens a (level 0 < 1 but its box pays: boxed), keeps b.
    const std::vector<int> level{2, 0, 0, 0, 0};
    Cut cut = take_cut(model, level, 1, boxes, kept);
    EXPECT_EQ(cut.box_nodes, (std::vector<int>{1}));
    EXPECT_EQ(cut.geometry_nodes, (std::vector<int>{4}));
    // A kept node keeps its whole sub-tree, though a child's own box would pay: a child of 30 triangles
    // (2,340 bytes) has a box of side 1 (1,224 + 6 x 5 x 5 texels x 8 / 3 = 1,624), its parent of 31
    // triangles (2,418) a box of side 10 (4,360).
    Model deep = tree(30, 0, 0);
    deep.nodes[1].primitives = {deep.nodes[2].primitives[0]};
    deep.nodes[1].primitives[0].positions.resize(3);
    deep.nodes[1].primitives[0].normals.resize(3);
    deep.nodes[1].primitives[0].indices.resize(3);
    deep.nodes[1].primitives[0].polygon_count = 1;
    std::vector<std::optional<OrientedBox>> deep_boxes{std::nullopt, cube(10), cube(1), std::nullopt,
                                                       std::nullopt};
    ASSERT_EQ(box_bytes_estimate(cube(1), sizing, true), 1624u);
    EXPECT_EQ(kept_subtrees(deep, deep_boxes, {false, true}, sizing, true),
              (std::vector<bool>{false, true, true, true, false}));
    deep_boxes[1] = cube(1);  // now a's box pays too
    EXPECT_EQ(kept_subtrees(deep, deep_boxes, {false, true}, sizing, true), (std::vector<bool>(5, false)));
    // A node without a box is never marked cheaper (nothing would replace it).
    boxes[4].reset();
    EXPECT_FALSE(kept_subtrees(model, boxes, {false, true}, sizing, true)[4]);
}
