#include "toolkit/lod/pages/level_pages.h"

#include <gtest/gtest.h>

namespace boxlod {
namespace {

// A face of `side` x `side` texels, all of one opaque colour but the texels a
// test clears (alpha 0).
BakedFace plain_face(int side, std::array<std::uint8_t, 4> color) {
    BakedFace face;
    face.color = Image8(side, side, 4, 0);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) std::copy(color.begin(), color.end(), face.color.at(x, y));
    face.normal = Image8(side, side, 3, 128);
    face.height = Image16(side, side, 1, 65535);
    face.covered = {0, 0, side, side};
    return face;
}

TEST(LevelPages, EachPageHasItsMaterialAndThreeTextures) {
    Model model;
    Atlas atlas;
    atlas.pages = {{64, 32}, {16, 16}};
    add_pages(model, atlas, 2.5f, true);
    ASSERT_EQ(model.materials.size(), 2u);
    ASSERT_EQ(model.textures.size(), 6u);
    for (int page = 0; page < 2; ++page) {
        const Material& material = model.materials[std::size_t(page)];
        EXPECT_EQ(material.base_color_texture, lod_page(page).color);
        EXPECT_EQ(material.normal_texture, lod_page(page).normal);
        EXPECT_EQ(material.height_texture, lod_page(page).height);
        EXPECT_EQ(material.height_depth, 2.5f);
        EXPECT_EQ(model.textures[std::size_t(lod_page(page).color)].image.width,
                  atlas.pages[std::size_t(page)].x());
    }
    const Image8& normal = model.textures[std::size_t(lod_page(1).normal)].image;
    EXPECT_EQ(std::vector<int>(normal.at(3, 3), normal.at(3, 3) + 3),
              (std::vector<int>{128, 128, 255}));  // the flat normal
    Model untextured;
    add_pages(untextured, atlas, 1, false);
    EXPECT_EQ(untextured.materials.size(), 1u);
    EXPECT_TRUE(untextured.textures.empty());
}

// A face is flat only when small enough and at least half covered; its colour
// is the covered texels' mean in linear light (sRGB 0 and 255 give 188, not 128).
TEST(LevelPages, AFlatFaceTakesItsCoveredTexelsMeanInLinearLight) {
    BakedFace face = plain_face(4, {255, 255, 255, 255});
    for (int x = 0; x < 4; ++x)
        for (int y = 0; y < 2; ++y)
            face.color.at(x, y)[0] = face.color.at(x, y)[1] = face.color.at(x, y)[2] = 0;
    const auto color = flat_color(face, face.covered, 8);
    ASSERT_TRUE(color);
    EXPECT_EQ(*color, (std::array<std::uint8_t, 4>{188, 188, 188, 255}));
    EXPECT_FALSE(flat_color(face, face.covered, 3));  // larger than flat_faces
    for (int x = 0; x < 4; ++x)
        for (int y = 0; y < 3; ++y) face.color.at(x, y)[3] = 0;
    EXPECT_FALSE(flat_color(face, face.covered, 8));  // a quarter covered
}

// Swatches start on 4-texel boundaries of the page, whatever their block's
// corner, and fill the block and its gutter with the nearest swatch's colour.
TEST(LevelPages, SwatchesLieOnCompressionBlocksAndFillTheirGutter) {
    Swatches swatches;
    swatches.colors = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
    swatches.columns = 2;
    const AtlasPlacement at{0, 5, 2, false};
    EXPECT_EQ(swatch_texel(swatches, at, 0), Eigen::Vector2i(8, 4));
    EXPECT_EQ(swatch_texel(swatches, at, 1), Eigen::Vector2i(12, 4));
    EXPECT_EQ(swatch_texel(swatches, at, 2), Eigen::Vector2i(8, 8));
    Model model;
    Atlas atlas;
    atlas.pages = {{32, 32}};
    add_pages(model, atlas, 1, true);
    place_swatches(swatches, at, 2, model);
    const Image8& color = model.textures[std::size_t(lod_page(0).color)].image;
    auto rgb = [&](int x, int y) { return std::vector<int>(color.at(x, y), color.at(x, y) + 3); };
    EXPECT_EQ(rgb(9, 5), (std::vector<int>{255, 0, 0}));
    EXPECT_EQ(rgb(13, 5), (std::vector<int>{0, 255, 0}));
    EXPECT_EQ(rgb(9, 9), (std::vector<int>{0, 0, 255}));
    EXPECT_EQ(rgb(13, 9), (std::vector<int>{0, 0, 255}));  // past the last swatch: the last one's colour
    EXPECT_EQ(rgb(3, 0), (std::vector<int>{255, 0, 0}));   // the gutter, up to 2 texels off the block
    EXPECT_EQ(color.at(2, 0)[3], 0);                       // beyond it, untouched
    EXPECT_EQ(model.textures[std::size_t(lod_page(0).height)].image16.at(9, 5)[0], 65535);
}

// A face's region lands at its placement with the gutter repeating its edge
// texels; heights scale from the face's depth to the page's.
TEST(LevelPages, AFaceIsPlacedWithItsGutterAndHeightsScaled) {
    BakedFace face = plain_face(4, {10, 20, 30, 255});
    face.color.at(3, 0)[0] = 99;  // the region's top-right texel
    face.height.at(3, 0)[0] = 65535 - 1000;
    Model model;
    Atlas atlas;
    atlas.pages = {{16, 16}};
    add_pages(model, atlas, 1, true);
    Texture &color = model.textures[0], &normal = model.textures[1], &height = model.textures[2];
    place_face(face, {1, 0, 3, 2}, {0, 4, 4, false}, 1, 0.5f, color, normal, height);
    EXPECT_EQ(color.image.at(6, 4)[0], 99);  // region (2, 0) at block (2, 0)
    EXPECT_EQ(color.image.at(7, 3)[0], 99);  // the gutter repeats the edge
    EXPECT_EQ(color.image.at(4, 4)[0], 10);
    EXPECT_EQ(color.image.at(3, 4)[0], 10);  // left gutter: the face's own texel beyond the region
    EXPECT_EQ(color.image.at(8, 4)[3], 0);   // past the gutter
    EXPECT_EQ(height.image16.at(6, 4)[0], 65535 - 500);
}

}  // namespace
}  // namespace boxlod
