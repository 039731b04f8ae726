#include "data_gen/materials.h"

#include "data_gen/textures.h"

#include <gtest/gtest.h>

namespace boxlod {

TEST(MaterialCache, OneMaterialPerAppearanceTexturesOnce) {
    Model model;
    MaterialCache cache;
    EXPECT_EQ(cache.index(model, {"brick", std::nullopt, ""}), 0);
    EXPECT_EQ(cache.index(model, {"glass", std::nullopt, ""}), 1);
    EXPECT_EQ(cache.index(model, {"brick", std::nullopt, ""}), 0);
    EXPECT_EQ(cache.index(model, {"brick", Eigen::Vector3f(1, 1, 1), ""}), 2);
    ASSERT_EQ(model.materials.size(), 3u);
    EXPECT_EQ(model.textures.size(), 4u);  // brick and glass, colour and normal each
    EXPECT_EQ(model.textures[0].name, "brick_color.png");
    EXPECT_EQ(model.textures[1].name, "brick_normal.png");
    EXPECT_EQ(model.materials[2].base_color_texture, 0);
    EXPECT_GT(model.materials[1].specular_color.x(), model.materials[0].specular_color.x());  // glass shines
}

TEST(MaterialCache, UntexturedMaterialsAndOverrides) {
    Model model;
    MaterialCache cache;
    int metal = cache.index(model, {"metal", std::nullopt, ""});
    EXPECT_EQ(model.materials[metal].base_color_texture, -1);
    EXPECT_TRUE(model.textures.empty());
    int wooden_metal = cache.index(model, {"metal", std::nullopt, "wood"});
    EXPECT_EQ(model.materials[wooden_metal].name, "metal_wood");
    EXPECT_EQ(model.textures[model.materials[wooden_metal].base_color_texture].name, "wood_color.png");
    EXPECT_FLOAT_EQ(cache.tile_metres({"metal", std::nullopt, ""}), 1);
    EXPECT_FLOAT_EQ(cache.tile_metres({"metal", std::nullopt, "wood"}), texture_tile_metres("wood"));
}

TEST(MaterialCache, ColourIsSrgbStoredLinear) {
    Model model;
    MaterialCache cache;
    cache.index(model, {"default", Eigen::Vector3f(0.5f, 0, 1), ""});
    EXPECT_EQ(model.materials[0].name, "default_8000ff");
    EXPECT_NEAR(model.materials[0].base_color.x(), 0.2158f, 1e-3f);
    EXPECT_FLOAT_EQ(model.materials[0].base_color.z(), 1);
}

TEST(MaterialNames, Known) {
    EXPECT_TRUE(is_material_name("roof_tiles"));
    EXPECT_FALSE(is_material_name("gold"));
    EXPECT_NE(material_names().find("asphalt"), std::string::npos);
}

}  // namespace boxlod
