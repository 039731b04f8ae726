#include "toolkit/model/model_subtree.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

Primitive triangle(int material, float x) {
    Primitive p;
    p.positions = {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}};
    p.indices = {0, 1, 2};
    p.polygon_count = 1;
    p.material = material;
    return p;
}

// root -> a (material 2) -> a1 (material 0), a2 (no material); root -> b (material 1).
// Material 2 uses textures 1 (colour) and 2 (normal); material 1 texture 0.
Model two_branches() {
    Model model;
    model.source = "two.gltf";
    for (int t = 0; t < 3; ++t)
        model.textures.push_back(
            {std::string("t") += std::to_string(t), Image8(1, 1, 4, std::uint8_t(t)), {}});
    for (int m = 0; m < 3; ++m) model.materials.push_back(Material{std::string("m") += std::to_string(m)});
    model.materials[1].base_color_texture = 0;
    model.materials[2].base_color_texture = 1;
    model.materials[2].normal_texture = 2;
    int root = add_node(model, -1, "root");
    int a = add_node(model, root, "a");
    int a1 = add_node(model, a, "a1");
    int b = add_node(model, root, "b");
    int a2 = add_node(model, a, "a2");  // added after b: a's children are not contiguous
    model.nodes[a].rule = "Mass";
    model.nodes[a].scope = OrientedBox{{1, 2, 3}, Eigen::Matrix3f::Identity(), {1, 1, 1}};
    model.nodes[a].primitives.push_back(triangle(2, 0));
    model.nodes[a1].primitives.push_back(triangle(0, 1));
    model.nodes[a2].primitives.push_back(triangle(-1, 2));
    model.nodes[b].primitives.push_back(triangle(1, 3));
    return model;
}

}  // namespace

TEST(ModelSubtree, ExtractsTheSubtreeWithOnlyTheMaterialsItUses) {
    Model model = two_branches();
    Model part = extract_subtree(model, 1);
    ASSERT_EQ(part.nodes.size(), 3u);
    EXPECT_EQ(part.source, "two.gltf");
    EXPECT_EQ(part.nodes[0].name, "a");
    EXPECT_EQ(part.nodes[0].parent, -1);
    EXPECT_EQ(part.nodes[0].rule, "Mass");
    ASSERT_TRUE(part.nodes[0].scope);
    EXPECT_EQ(part.nodes[0].scope->center, Eigen::Vector3f(1, 2, 3));
    EXPECT_EQ(part.nodes[0].children, (std::vector<int>{1, 2}));
    EXPECT_EQ(part.nodes[1].name, "a1");
    EXPECT_EQ(part.nodes[2].name, "a2");
    EXPECT_EQ(part.nodes[1].parent, 0);
    EXPECT_EQ(part.nodes[2].parent, 0);
    // Materials 2 then 0 in first-use order; textures 1 and 2 of material 2 only.
    ASSERT_EQ(part.materials.size(), 2u);
    EXPECT_EQ(part.materials[0].name, "m2");
    EXPECT_EQ(part.materials[1].name, "m0");
    ASSERT_EQ(part.textures.size(), 2u);
    EXPECT_EQ(part.textures[0].name, "t1");
    EXPECT_EQ(part.textures[1].name, "t2");
    EXPECT_EQ(part.materials[0].base_color_texture, 0);
    EXPECT_EQ(part.materials[0].normal_texture, 1);
    EXPECT_EQ(part.nodes[0].primitives[0].material, 0);
    EXPECT_EQ(part.nodes[1].primitives[0].material, 1);
    EXPECT_EQ(part.nodes[2].primitives[0].material, -1);
    EXPECT_EQ(part.nodes[1].primitives[0].positions, model.nodes[2].primitives[0].positions);
    validate_model(part);
}

TEST(ModelSubtree, TheRootGivesTheWholeTree) {
    Model model = two_branches();
    Model whole = extract_subtree(model, 0);
    EXPECT_EQ(whole.nodes.size(), model.nodes.size());
    EXPECT_EQ(whole.materials.size(), 3u);
    EXPECT_EQ(whole.textures.size(), 3u);
    EXPECT_EQ(tree_depth(whole), tree_depth(model));
}

TEST(ModelSubtree, APartOfAnLodIsAnLod) {
    Model lod = two_branches();
    lod.is_lod = true;  // built from never again, whole or in part (tiles builds each object's sub-tree)
    EXPECT_TRUE(extract_subtree(lod, 1).is_lod);
    EXPECT_FALSE(extract_subtree(two_branches(), 1).is_lod);
}

// A child scaled to nothing draws nothing and is no object: `tiles` refused a whole glTF city for one,
// saying the scene had no triangle.
TEST(ModelSubtree, ObjectsAreTheChildrenThatDrawAndTheRootsOwnGeometry) {
    Model city = two_branches();
    const int flat = add_node(city, 0, "flat");
    city.nodes[std::size_t(flat)].primitives.push_back(triangle(0, 5));
    for (Eigen::Vector3f& p : city.nodes[std::size_t(flat)].primitives[0].positions) p = {5, 0, 0};
    EXPECT_EQ(object_nodes(city), (std::vector<int>{1, 3}));
    city.nodes[0].primitives.push_back(triangle(0, 9));
    EXPECT_EQ(object_nodes(city), (std::vector<int>{-1, 1, 3}));
    Model alone = two_branches();
    for (int n = 1; n < int(alone.nodes.size()); ++n) alone.nodes[std::size_t(n)].primitives.clear();
    alone.nodes[0].primitives.push_back(triangle(0, 9));
    EXPECT_EQ(object_nodes(alone), (std::vector<int>{0}));
}
