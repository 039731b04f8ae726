#include "toolkit/lod/hybrid/paid_textures.h"

#include "toolkit/model/cost.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// Three materials: 0 samples texture 0, 1 samples textures 0 and 1, 2 samples
// texture 2, which holds the same texels as texture 0.
Model three_materials() {
    Model model;
    model.textures.push_back({"a", Image8(64, 64, 3, 10)});
    model.textures.push_back({"b", Image8(16, 16, 3, 20)});
    model.textures.push_back({"a again", Image8(64, 64, 3, 10)});
    model.materials.resize(3);
    model.materials[0].base_color_texture = 0;
    model.materials[1].base_color_texture = 0;
    model.materials[1].normal_texture = 1;
    model.materials[2].base_color_texture = 2;
    return model;
}

}  // namespace

TEST(PaidTextures, TexturesOfEqualTexelsArePaidOnce) {
    const Model model = three_materials();
    const PaidTextures paid = paid_textures(model);
    ASSERT_EQ(paid.bytes.size(), 2u);
    EXPECT_EQ(paid.of_material[0], (std::vector<int>{0}));
    EXPECT_EQ(paid.of_material[1], (std::vector<int>{0, 1}));
    EXPECT_EQ(paid.of_material[2], (std::vector<int>{0}));
    // As cost.h counts them: BC1 colour, BC5 normals, each with its mips.
    EXPECT_EQ(paid.bytes[0], double(block_compressed_bytes(64, 64, GpuFormat::bc1)));
    EXPECT_EQ(paid.bytes[1], double(block_compressed_bytes(16, 16, GpuFormat::bc5)));
}

TEST(PaidTextures, AChangePaysForWhatItBringsInAndGetsBackWhatItFrees) {
    const Model model = three_materials();
    const PaidTextures paid = paid_textures(model);
    const std::vector<int> first = paid.of_material[0], both = paid.of_material[1], none;
    DrawnTextures drawn(paid);
    EXPECT_EQ(drawn.apply(none, {&first}), paid.bytes[0]);
    EXPECT_EQ(drawn.change(none, {&first}), 0);              // already paid for
    EXPECT_EQ(drawn.change(first, {&both}), paid.bytes[1]);  // texture 0 stays paid while both sample it
    EXPECT_EQ(drawn.change(first, {}), -paid.bytes[0]);      // and is freed with its last part
    EXPECT_EQ(drawn.change(first, {}), -paid.bytes[0]);      // change() left the count as it was
    EXPECT_EQ(drawn.apply(first, {&none, &both, &both}), paid.bytes[1]);
    EXPECT_EQ(drawn.change(both, {}), 0);  // another part still samples both
}

TEST(PaidTextures, ASubtreeSamplesWhatItsNodesSampleAndFreesWhatOnlyItSamples) {
    Model model = three_materials();
    add_node(model, -1, "root");
    add_node(model, 0, "a");
    add_node(model, 1, "a's child");
    add_node(model, 0, "b");
    model.nodes[2].primitives.emplace_back().material = 1;
    model.nodes[3].primitives.emplace_back().material = 2;
    const PaidTextures paid = paid_textures(model);
    const auto own = node_textures(model, paid), subtree = subtree_textures(model, paid);
    EXPECT_EQ(own[0], std::vector<int>{});
    EXPECT_EQ(subtree[0], (std::vector<int>{0, 1}));
    EXPECT_EQ(subtree[1], (std::vector<int>{0, 1}));
    EXPECT_EQ(subtree[3], (std::vector<int>{0}));
    // Texture 0 is sampled under a and under b: only the root's sub-tree can free it.
    const auto exclusive = exclusive_textures(model, paid);
    EXPECT_EQ(exclusive[0], (std::vector<int>{0, 1}));
    EXPECT_EQ(exclusive[1], (std::vector<int>{1}));
    EXPECT_EQ(exclusive[2], (std::vector<int>{1}));
    EXPECT_EQ(exclusive[3], std::vector<int>{});
}
