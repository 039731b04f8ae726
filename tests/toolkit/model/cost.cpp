#include "toolkit/model/cost.h"

#include "lod_scene.h"
#include "test_support.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/lod/hybrid/draw_calls.h"
#include "toolkit/lod/lod_export.h"

#include <gtest/gtest.h>

namespace boxlod {
namespace {

TEST(Cost, MipChainsCountEveryLevelDownToOneTexel) {
    EXPECT_EQ(mip_chain_texels(4, 4), 16u + 4 + 1);
    EXPECT_EQ(mip_chain_texels(8, 2), 16u + 4 + 2 + 1);  // 8x2, 4x1, 2x1, 1x1
    EXPECT_EQ(mip_chain_texels(1, 1), 1u);
    EXPECT_EQ(mip_chain_texels(0, 7), 0u);
}

TEST(Cost, BlockCompressionTakesEightOrSixteenBytesPerFourByFourBlock) {
    // 256^2: 64^2 + 32^2 + 16^2 + 8^2 + 4^2 + 2^2 + 1 blocks, and 4x4, 2x2, 1x1 one block each.
    const std::uint64_t blocks = 4096 + 1024 + 256 + 64 + 16 + 4 + 1 + 1 + 1;
    EXPECT_EQ(block_compressed_bytes(256, 256, GpuFormat::bc1), blocks * 8);
    EXPECT_EQ(block_compressed_bytes(256, 256, GpuFormat::bc4), blocks * 8);
    EXPECT_EQ(block_compressed_bytes(256, 256, GpuFormat::bc5), blocks * 16);
    EXPECT_EQ(block_compressed_bytes(256, 256, GpuFormat::bc7), blocks * 16);
    EXPECT_EQ(block_compressed_bytes(5, 3, GpuFormat::bc4), (2u + 1 + 1) * 8);  // 5x3: 2x1 blocks, 2x1, 1x1
}

// One textured quad with a colour map, a normal map and a 16-bit height map.
Model textured_quad(std::uint8_t alpha) {
    Model model;
    add_node(model, -1, "quad");
    Primitive& p = model.nodes[0].primitives.emplace_back();
    test::add_quad(p, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});  // positions, normals, uvs
    p.material = 0;
    Material material;
    material.base_color_texture = 0;
    material.normal_texture = 1;
    material.height_texture = 2;
    model.materials = {material};
    Texture color{"c.png", Image8(8, 8, 4, 255), {}};
    color.image.pixels[3] = alpha;
    model.textures = {color,
                      {"n.png", Image8(4, 4, 3, 128), {}},
                      {"h.png", {}, Image16(4, 4, 1, 0)},
                      {"unused.png", Image8(64, 64, 4, 0), {}}};
    return model;
}

TEST(Cost, HandComputedQuad) {
    ModelCost cost = model_cost(textured_quad(0));
    EXPECT_EQ(cost.draw_calls, 1u);
    EXPECT_EQ(cost.mesh_bytes, 4u * (12 + 12 + 8) + 6 * 2);  // 16-bit indices
    // Colour RGBA8 8x8 + normal RGB8 4x4 + height 16-bit 4x4, each with its mips; the unused texture is not
    // paid.
    EXPECT_EQ(cost.texture_bytes,
              4u * (64 + 16 + 4 + 1) + 3 * (16 + 4 + 1) + 2 * (16 + 4 + 1));  // RGBA: one texel is clear
    // Cut-out alpha: BC1 (4 + 1 + 1 + 1 blocks); BC5 and BC4 for 4x4, 2x2, 1x1.
    EXPECT_EQ(cost.texture_bytes_gpu, 7u * 8 + 3 * 16 + 3 * 8);
    EXPECT_EQ(cost.bytes(), cost.mesh_bytes + cost.texture_bytes_gpu);
    // An opaque colour map is written RGB8.
    EXPECT_EQ(model_cost(textured_quad(255)).texture_bytes, cost.texture_bytes - (64 + 16 + 4 + 1));
}

TEST(Cost, PartialAlphaNeedsBc7) {
    ModelCost cut_out = model_cost(textured_quad(0)), blended = model_cost(textured_quad(100));
    EXPECT_EQ(blended.texture_bytes_gpu - cut_out.texture_bytes_gpu,
              7u * 8);  // 16 instead of 8 bytes a block
}

TEST(Cost, SharedTexturesArePaidOnceWhenModelsAreCombined) {
    CostParts a = cost_parts(textured_quad(0)), b = cost_parts(textured_quad(0)),
              c = cost_parts(textured_quad(100));
    ModelCost one = combined_cost({&a}), two = combined_cost({&a, &b}), other = combined_cost({&a, &c});
    EXPECT_EQ(two.mesh_bytes, 2 * one.mesh_bytes);
    EXPECT_EQ(two.draw_calls, 2u);
    EXPECT_EQ(two.texture_bytes, one.texture_bytes);
    // Another colour texture is paid for; the equal normal and height maps are not.
    EXPECT_EQ(other.texture_bytes, one.texture_bytes + 4u * (64 + 16 + 4 + 1));
}

// A material's flat-shaded part (no normals, as simplified IFC parts come
// out) cannot share a mesh with its smooth ones: one more draw call, as many as
// the merged level ships.
TEST(Cost, EachMaterialsVertexLayoutIsADrawCall) {
    Model model = textured_quad(255);
    Primitive flat = model.nodes[0].primitives[0];
    flat.normals.clear();
    model.nodes[std::size_t(add_node(model, 0, "flat"))].primitives = {
        flat, Primitive{}};  // the empty one is not drawn
    EXPECT_EQ(model_cost(model).draw_calls, 2u);
    std::size_t shipped = 0;
    for (const Node& node : merge_draw_calls(model, "level").nodes) shipped += node.primitives.size();
    EXPECT_EQ(shipped, 2u);
    model.nodes[1].primitives[0].normals = model.nodes[0].primitives[0].normals;
    EXPECT_EQ(model_cost(model).draw_calls, 1u);
}

// A render mode pays for the maps it draws: none untextured, colour for
// albedo, colour and normal for normal mapping, and the height map too for
// parallax and pom. A texture two maps share is paid where either is drawn.
TEST(Cost, EachRenderModePaysForTheMapsItDraws) {
    Model model = textured_quad(0);
    const std::uint64_t color = 4u * (64 + 16 + 4 + 1), normal = 3u * (16 + 4 + 1),
                        height = 2u * (16 + 4 + 1);
    const std::uint64_t color_gpu = 7u * 8, normal_gpu = 3u * 16, height_gpu = 3u * 8;
    CostParts parts = cost_parts(model);
    auto texture_bytes = [&](RenderMode mode) { return drawn_cost({&parts}, mode).texture_bytes; };
    EXPECT_EQ(texture_bytes(RenderMode::untextured), 0u);
    EXPECT_EQ(texture_bytes(RenderMode::albedo), color);
    EXPECT_EQ(texture_bytes(RenderMode::normal), color + normal);
    EXPECT_EQ(texture_bytes(RenderMode::parallax), color + normal + height);
    EXPECT_EQ(texture_bytes(RenderMode::pom), color + normal + height);
    EXPECT_EQ(drawn_cost({&parts}, RenderMode::normal).texture_bytes_gpu, color_gpu + normal_gpu);
    EXPECT_EQ(drawn_cost({&parts}, RenderMode::pom).texture_bytes_gpu,
              combined_cost({&parts}).texture_bytes_gpu);
    for (const EnumEntry<RenderMode>& mode : render_modes()) {
        const ModelCost drawn = drawn_cost({&parts}, mode.value);
        EXPECT_EQ(drawn.mesh_bytes, parts.mesh_bytes) << mode.name;  // vertex buffers as exported
        EXPECT_EQ(drawn.draw_calls, 1u) << mode.name;
    }
    EXPECT_EQ(texture_bytes(RenderMode::normal) + height, model_cost(model).texture_bytes);

    // A second quad whose colour map is the first one's height map: albedo loads it, stored as first sampled.
    Primitive second = model.nodes[0].primitives[0];
    second.material = 1;
    model.nodes[0].primitives.push_back(second);
    Material colored_by_height;
    colored_by_height.base_color_texture = 2;
    model.materials.push_back(colored_by_height);
    CostParts shared = cost_parts(model);
    EXPECT_EQ(drawn_cost({&shared}, RenderMode::albedo).texture_bytes, color + height);
    EXPECT_EQ(drawn_cost({&shared}, RenderMode::pom).texture_bytes, color + normal + height);  // paid once
    EXPECT_EQ(drawn_cost({&shared}, RenderMode::albedo).texture_bytes_gpu, color_gpu + height_gpu);
}

// mesh_bytes is what the export writes: an exported LoD's .bin holds exactly its
// vertex and index buffers, and the statistics report the same numbers.
TEST(Cost, MeshBytesAreTheExportedBinAndPagesAreCounted) {
    Model model = test::lod_test_building();
    LodParameters p;
    set_manual(p);  // every sub-tree boxed: pages at level 2
    p.distance = 20;
    p.resolution = 200;
    p.min_texture_size = 64;
    Chain chain(model, p, 2);
    Lod lod = chain.build(2);
    ModelCost cost = model_cost(lod.model);
    EXPECT_EQ(value_of(lod.statistics, "mesh_bytes_lod"), std::to_string(cost.mesh_bytes));
    EXPECT_EQ(value_of(lod.statistics, "bytes_original"), std::to_string(model_cost(model).bytes()));
    ASSERT_FALSE(lod.atlas.pages.empty());
    // Per page: RGBA8 colour, RGB8 normal, 16-bit height, each with mips; plus the kept parts' bricks (32^2
    // RGB8).
    std::uint64_t page_bytes = 0;
    for (const Eigen::Vector2i& page : lod.atlas.pages)
        page_bytes += mip_chain_texels(page.x(), page.y()) * (4 + 3 + 2);
    EXPECT_GE(cost.texture_bytes, page_bytes);
    EXPECT_LE(cost.texture_bytes, page_bytes + mip_chain_texels(32, 32) * 3);

    auto folder = test::scratch_folder("cost_export");
    export_lod(std::move(lod), chain.parameters(), folder.string(), "house", Image8(4, 4, 3, 0), 1);
    EXPECT_EQ(std::filesystem::file_size(folder / "house.bin"), cost.mesh_bytes);
}

}  // namespace
}  // namespace boxlod
