#include "toolkit/formats/model_bytes.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// A model with a value in every kind of field.
Model every_field() {
    Model model;
    model.source = "house.ifc";
    model.reference_system = "EPSG:7415";
    model.read_files = {"textures/color.png", "height.png"};
    model.is_lod = true;
    model.lod_params = {{"level", "2"}, {"mode", ""}};
    Material brick{"brick"};
    brick.base_color = {0.6f, 0.3f, 0.2f, 0.5f};
    brick.base_color_texture = 0;
    brick.height_texture = 1;
    brick.shininess = 7;
    brick.glossiness = 0.25f;
    brick.specular_extension = SpecularExtension{0.5f, {1, 2, 3}, 0, -1};
    brick.alpha_mode = AlphaMode::blend;
    model.materials = {brick, Material{"plain"}};
    Texture color{"color.png", Image8(2, 1, 3, 7)};
    color.wrap = Wrap::clamp;
    Texture height{"height", {}, Image16(1, 2, 1, 60000)};
    model.textures = {color, height};
    const int root = add_node(model, -1, "root");
    const int wall = add_node(model, root, "wall");
    model.nodes[std::size_t(wall)].rule = "Wall";
    model.nodes[std::size_t(wall)].instance_of = "mesh 3";
    model.nodes[std::size_t(wall)].scope = OrientedBox{{1, 2, 3}, Eigen::Matrix3f::Identity(), {4, 5, 6}};
    Primitive& p = model.nodes[std::size_t(wall)].primitives.emplace_back();
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    p.uvs = {{0, 0}, {1, 0}, {0, 1}};
    p.tangents = {{1, 0, 0, -1}, {1, 0, 0, -1}, {1, 0, 0, -1}};
    p.indices = {0, 1, 2};
    p.polygon_count = 1;
    p.material = 0;
    return model;
}

}  // namespace

TEST(ModelBytes, EveryFieldComesBack) {
    const Model model = every_field();
    const std::string bytes = model_bytes(model);
    const Model back = model_from_bytes(bytes);
    EXPECT_EQ(model_bytes(back), bytes);
    EXPECT_EQ(back.source, "house.ifc");
    EXPECT_EQ(back.reference_system, "EPSG:7415");
    EXPECT_EQ(back.read_files, model.read_files);
    EXPECT_TRUE(back.is_lod);
    EXPECT_EQ(back.lod_params, model.lod_params);
    EXPECT_EQ(back.materials, model.materials);
    ASSERT_EQ(back.textures.size(), 2u);
    EXPECT_EQ(back.textures[0].image.pixels, model.textures[0].image.pixels);
    EXPECT_EQ(back.textures[0].wrap, Wrap::clamp);
    EXPECT_EQ(back.textures[1].image16.pixels, model.textures[1].image16.pixels);
    ASSERT_EQ(back.nodes.size(), 2u);
    EXPECT_EQ(back.nodes[0].children, std::vector<int>{1});
    const Node& wall = back.nodes[1];
    EXPECT_EQ(wall.parent, 0);
    EXPECT_EQ(wall.rule, "Wall");
    EXPECT_EQ(wall.instance_of, "mesh 3");
    ASSERT_TRUE(wall.scope);
    EXPECT_EQ(wall.scope->half_extents, Eigen::Vector3f(4, 5, 6));
    const Primitive &p = wall.primitives.at(0), &q = model.nodes[1].primitives[0];
    EXPECT_EQ(p.positions, q.positions);
    EXPECT_EQ(p.normals, q.normals);
    EXPECT_EQ(p.uvs, q.uvs);
    EXPECT_EQ(p.tangents, q.tangents);
    EXPECT_EQ(p.indices, q.indices);
    EXPECT_EQ(p.polygon_count, 1u);
    EXPECT_FALSE(back.nodes[0].scope);
}

TEST(ModelBytes, BytesNotWrittenWholeAreRefused) {
    const std::string bytes = model_bytes(every_field());
    EXPECT_THROW(model_from_bytes(std::string_view(bytes).substr(0, bytes.size() - 1)), std::logic_error);
    EXPECT_THROW(model_from_bytes(bytes + "x"), std::logic_error);
    std::string huge_count = bytes;
    huge_count[huge_count.size() - 9] = '\xff';  // the high byte of the 16-bit pixels' count
    EXPECT_THROW(model_from_bytes(huge_count), std::logic_error);
}
