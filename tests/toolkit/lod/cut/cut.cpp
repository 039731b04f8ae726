#include "toolkit/lod/cut/cut.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {
// root(3) -> a(2) -> a1(0, geometry), a2(1, geometry); root -> b(2, geometry) -> b1(0, no geometry)
Model tree() {
    Model model;
    add_node(model, -1, "root");
    int a = add_node(model, 0, "a");
    add_node(model, a, "a1");
    add_node(model, a, "a2");
    int b = add_node(model, 0, "b");
    add_node(model, b, "b1");
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.indices = {0, 1, 2};
    for (int n : {2, 3, 4}) model.nodes[n].primitives.push_back(p);
    return model;
}
std::vector<std::optional<OrientedBox>> boxes_for(const Model& model) {
    // Every node whose sub-tree has geometry has a box (its content does not matter here).
    std::vector<std::optional<OrientedBox>> boxes(model.nodes.size());
    for (int n : {0, 1, 2, 3, 4}) boxes[n] = OrientedBox{};
    return boxes;
}
}  // namespace

TEST(Cut, LevelZeroIsTheOriginal) {
    Model model = tree();
    std::vector<int> level{3, 2, 0, 1, 2, 0};
    Cut cut = take_cut(model, level, 0, boxes_for(model));
    EXPECT_EQ(cut.used_nodes, (std::vector<int>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(cut.geometry_nodes, (std::vector<int>{2, 3, 4}));
    EXPECT_TRUE(cut.box_nodes.empty());
}

TEST(Cut, NodesBelowTheCurrentLevelBecomeBoxes) {
    Model model = tree();
    std::vector<int> level{3, 2, 0, 1, 2, 0};
    Cut cut = take_cut(model, level, 1, boxes_for(model));
    EXPECT_EQ(cut.used_nodes, (std::vector<int>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(cut.geometry_nodes, (std::vector<int>{3, 4}));
    EXPECT_EQ(cut.box_nodes, (std::vector<int>{2}));  // b1 has no geometry: no box

    cut = take_cut(model, level, 3, boxes_for(model));
    EXPECT_EQ(cut.used_nodes, (std::vector<int>{0, 1, 4}));
    EXPECT_TRUE(cut.geometry_nodes.empty());
    EXPECT_EQ(cut.box_nodes, (std::vector<int>{1, 4}));

    cut = take_cut(model, level, 4, boxes_for(model));  // c = N: the root's box alone
    EXPECT_EQ(cut.used_nodes, (std::vector<int>{0}));
    EXPECT_EQ(cut.box_nodes, (std::vector<int>{0}));
}

TEST(Cut, DescendantsOfAReplacedNodeAreNeverVisited) {
    Model model = tree();
    std::vector<int> level{3, 0, 5, 5, 2, 0};  // a's children rank higher, but a is replaced first
    Cut cut = take_cut(model, level, 1, boxes_for(model));
    EXPECT_EQ(cut.used_nodes, (std::vector<int>{0, 1, 4, 5}));
    EXPECT_EQ(cut.box_nodes, (std::vector<int>{1}));
}

// Beyond the manual: a kept node keeps its own geometry and its children are visited.
TEST(Cut, KeptNodesKeepTheirGeometryAndOpenTheirChildren) {
    Model model = tree();
    std::vector<int> level{3, 2, 0, 1, 2, 0};
    std::vector<bool> kept{false, true, false, true, true, false};  // a, a2, b
    Cut cut = take_cut(model, level, 3, boxes_for(model), kept);
    EXPECT_EQ(cut.used_nodes, (std::vector<int>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(cut.box_nodes, (std::vector<int>{2}));          // a's child a1 is not kept: boxed
    EXPECT_EQ(cut.geometry_nodes, (std::vector<int>{3, 4}));  // a2 and b kept
    // Without the marks a and b are boxed.
    EXPECT_EQ(take_cut(model, level, 3, boxes_for(model)).box_nodes, (std::vector<int>{1, 4}));
}
