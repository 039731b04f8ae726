#include "data_gen/textures.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

namespace boxlod {

TEST(ProceduralTexture, EveryKindIsDeterministicAndDistinct) {
    std::vector<std::vector<std::uint8_t>> seen;
    for (const char* name : {"brick", "plaster", "roof_tiles", "glass", "wood", "stone"}) {
        ASSERT_TRUE(is_texture_name(name));
        ProceduralTexture a = procedural_texture(name, 64), b = procedural_texture(name, 64);
        EXPECT_EQ(a.color.pixels, b.color.pixels) << name;
        EXPECT_EQ(a.normal.pixels, b.normal.pixels) << name;
        EXPECT_EQ(a.color.width, 64);
        EXPECT_EQ(a.color.channels, 4);
        EXPECT_GT(a.tile_metres, 0);
        EXPECT_FLOAT_EQ(texture_tile_metres(name), a.tile_metres);
        for (const auto& other : seen) EXPECT_NE(a.color.pixels, other) << name;
        seen.push_back(a.color.pixels);
    }
    EXPECT_FALSE(is_texture_name("marble"));
}

TEST(ProceduralTexture, HasDetail) {
    ProceduralTexture brick = procedural_texture("brick");
    EXPECT_EQ(brick.color.width, 128);
    int lo = 255, hi = 0;
    for (std::size_t i = 0; i < brick.color.pixels.size(); i += 4) {
        lo = std::min<int>(lo, brick.color.pixels[i]);
        hi = std::max<int>(hi, brick.color.pixels[i]);
    }
    EXPECT_GT(hi - lo, 60);  // mortar and bricks differ
}

TEST(ProceduralTexture, NormalMapsHoldUnitVectorsFacingOut) {
    ProceduralTexture stone = procedural_texture("stone", 64);
    bool tilted = false;
    for (std::size_t i = 0; i < stone.normal.pixels.size(); i += 4) {
        Eigen::Vector3d n;
        for (int c = 0; c < 3; ++c) n[c] = stone.normal.pixels[i + c] / 255.0 * 2 - 1;
        EXPECT_NEAR(n.norm(), 1, 0.02);
        EXPECT_GT(n.z(), 0);
        tilted = tilted || n.z() < 0.95;
        EXPECT_EQ(stone.normal.pixels[i + 3], 255);
    }
    EXPECT_TRUE(tilted);
}

}  // namespace boxlod
