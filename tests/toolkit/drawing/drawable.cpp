#include "toolkit/drawing/drawable.h"

#include <gtest/gtest.h>

#include <thread>

using namespace boxlod;

namespace {

Texture texture_of(const std::string& name, std::uint8_t value, int size = 4) {
    Image8 image(size, size, 4, value);
    image.pixels[0] = std::uint8_t(value + 1);  // not flat
    return {name, image, {}};
}

// Textures 0 and 1 hold the same texels under other names; 2 differs in one texel.
Model model_with_textures() {
    Model model;
    model.textures = {texture_of("a.png", 100), texture_of("copy of a.png", 100), texture_of("b.png", 100)};
    model.textures[2].image.pixels[5] = 7;
    for (int t = 0; t < 3; ++t) {
        Material material;
        material.base_color_texture = t;
        model.materials.push_back(material);
    }
    model.materials[2].normal_texture = 0;  // the same image decoded as linear data
    return model;
}

TEST(TextureCache, EqualTexelsDecodeOnceWhateverTheirName) {
    Model model = model_with_textures();
    TextureCache cache;
    DecodedTextures first = decode_textures(model, &cache), second = decode_textures(model, &cache);
    EXPECT_EQ(first.color[0], first.color[1]);   // same texels: one decoded texture
    EXPECT_NE(first.color[0], first.color[2]);   // one texel apart
    EXPECT_NE(first.color[0], first.linear[0]);  // sRGB and linear decode differently
    EXPECT_EQ(first.color[2], second.color[2]);  // a second model shares the first's
    EXPECT_EQ(cache.size(), 3u);
}

TEST(TextureCache, DecodesTheSameTexelsAsWithoutIt) {
    Model model = model_with_textures();
    TextureCache cache;
    DecodedTextures cached = decode_textures(model, &cache), plain = decode_textures(model);
    for (int t = 0; t < 3; ++t) {
        ASSERT_TRUE(plain.color[t] && cached.color[t]);
        EXPECT_EQ(plain.color[t]->format, cached.color[t]->format);
        ASSERT_EQ(plain.color[t]->levels.size(), cached.color[t]->levels.size());
        for (std::size_t l = 0; l < plain.color[t]->levels.size(); ++l)
            EXPECT_EQ(plain.color[t]->levels[l].rgba8, cached.color[t]->levels[l].rgba8);
    }
    EXPECT_FALSE(plain.linear[1]);              // unused as linear data: not decoded
    EXPECT_NE(plain.color[0], plain.color[1]);  // without a cache nothing is shared
}

TEST(TextureCache, ThreadsRacingForOneTextureGetTheSameOne) {
    Texture texture = texture_of("a.png", 42, 64);
    TextureCache cache;
    std::shared_ptr<const MipTexture> got[4];
    std::vector<std::thread> threads;
    for (auto& slot : got) threads.emplace_back([&] { slot = cache.decode(texture, ColorSpace::srgb); });
    for (auto& t : threads) t.join();
    for (auto& slot : got) EXPECT_EQ(slot, got[0]);
    EXPECT_EQ(cache.size(), 1u);
}

}  // namespace
