#include "toolkit/model/material_merge.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

Primitive triangle_of(int material) {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.indices = {0, 1, 2};
    p.polygon_count = 1;
    p.material = material;
    return p;
}

}  // namespace

TEST(MaterialMerge, CopiesMergeAndMaterialsNothingDrawsGo) {
    Model model;
    Material brick{"brick"};
    brick.base_color = {0.6f, 0.3f, 0.2f, 1};
    Material glass{"glass"};
    glass.alpha_mode = AlphaMode::mask;
    Material renamed = brick;
    renamed.name = "brick_2";  // another name: another material
    // 0 brick, 1 unused, 2 copy of brick, 3 glass, 4 brick_2, 5 unused copy of glass
    model.materials = {brick, Material{"unused"}, brick, glass, renamed, glass};
    int root = add_node(model, -1, "root");
    for (int m : {0, 2, 3, 4, -1})
        model.nodes[std::size_t(add_node(model, root, "part"))].primitives.push_back(triangle_of(m));
    EXPECT_EQ(merge_materials(model), 3u);
    ASSERT_EQ(model.materials.size(), 3u);
    EXPECT_EQ(model.materials[0], brick);
    EXPECT_EQ(model.materials[1], glass);
    EXPECT_EQ(model.materials[2].name, "brick_2");
    std::vector<int> drawn;
    for (const Node& node : model.nodes)
        for (const Primitive& primitive : node.primitives) drawn.push_back(primitive.material);
    EXPECT_EQ(drawn, (std::vector<int>{0, 0, 1, 2, -1}));
    EXPECT_EQ(merge_materials(model), 0u);  // nothing left to merge
}
