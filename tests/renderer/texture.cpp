#include "renderer/texture.h"

#include <gtest/gtest.h>
#include "base/random.h"

#include <bit>
#include <cstdint>
#include <limits>
#include <utility>

using namespace boxlod;

namespace {
// A 4x2 linear texture with distinct red values 0, 40, 80, ... per texel.
MipTexture ramp(Wrap wrap) {
    Image8 image(4, 2, 4, 255);
    for (int i = 0; i < 8; ++i) image.pixels[i * 4] = std::uint8_t(i * 40);
    MipTexture texture = make_texture(image, ColorSpace::linear, wrap);
    return texture;
}
float red(std::uint8_t v) { return float(v) / 255.0f; }
}  // namespace

TEST(Texture, TexelCentresReturnTexelsExactly) {
    MipTexture t = ramp(Wrap::clamp);
    t.filter = Filter::bilinear;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            EXPECT_FLOAT_EQ(sample(t, {(x + 0.5f) / 4, (y + 0.5f) / 2}).x(),
                            red(std::uint8_t((y * 4 + x) * 40)));
}

TEST(Texture, BilinearBlendsNeighbours) {
    MipTexture t = ramp(Wrap::clamp);
    // Halfway between texels (0,0) and (1,0), a quarter of the way down to row 1.
    Eigen::Vector4f v = sample(t, {1.0f / 4, (0.5f + 0.25f) / 2});
    float expected = (red(0) * 0.5f + red(40) * 0.5f) * 0.75f + (red(160) * 0.5f + red(200) * 0.5f) * 0.25f;
    EXPECT_NEAR(v.x(), expected, 1e-6f);
}

TEST(Texture, ClampAndRepeatDifferAtTheBorder) {
    MipTexture clamp = ramp(Wrap::clamp), repeat = ramp(Wrap::repeat);
    Eigen::Vector2f left_edge(0, 0.25f);  // between texel -1 and 0 horizontally
    EXPECT_FLOAT_EQ(sample(clamp, left_edge).x(), red(0));
    EXPECT_NEAR(sample(repeat, left_edge).x(), (red(0) + red(120)) / 2, 1e-6f);
    EXPECT_FLOAT_EQ(sample(repeat, {1.125f + 2, 0.25f}).x(), red(0));  // whole periods away
}

TEST(Texture, MipChainHalvesDownToOneTexelAndAverages) {
    MipTexture t = ramp(Wrap::clamp);
    ASSERT_EQ(t.levels.size(), 3u);
    EXPECT_EQ(t.levels[1].width, 2);
    EXPECT_EQ(t.levels[1].height, 1);
    EXPECT_EQ(t.levels[2].width, 1);
    // Levels keep the image's 8-bit encoding: averages round to the nearest step.
    EXPECT_NEAR(texel(t, 1, 0, 0).x(), (red(0) + red(40) + red(160) + red(200)) / 4, 0.5f / 255);
    EXPECT_NEAR(texel(t, 2, 0, 0).x(), (texel(t, 1, 0, 0).x() + texel(t, 1, 1, 0).x()) / 2, 0.5f / 255);
}

TEST(Texture, TrilinearBlendsLevels) {
    MipTexture t = ramp(Wrap::clamp);
    Eigen::Vector2f uv(0.25f, 0.5f);
    Eigen::Vector4f a = sample(t, uv, 1), b = sample(t, uv, 2), half = sample(t, uv, 1.5f);
    EXPECT_NEAR(half.x(), (a.x() + b.x()) / 2, 1e-6f);
    EXPECT_EQ(sample(t, uv, 10).x(), sample(t, uv, 2).x());  // clamps to the last level
}

TEST(Texture, MipLevelFollowsTexelsPerPixel) {
    MipTexture t = make_texture(Image8(256, 256, 4), ColorSpace::linear);
    EXPECT_FLOAT_EQ(mip_level(t, {1.0f / 256, 0}, {0, 1.0f / 256}), 0);
    EXPECT_FLOAT_EQ(mip_level(t, {4.0f / 256, 0}, {0, 1.0f / 256}), 2);
}

TEST(Texture, SrgbTexturesDecodeToLinear) {
    Image8 image(1, 1, 4, 128);
    EXPECT_FLOAT_EQ(texel(make_texture(image, ColorSpace::srgb), 0, 0, 0).x(), srgb_to_linear(128));
    EXPECT_FLOAT_EQ(texel(make_texture(image, ColorSpace::srgb), 0, 0, 0).w(),
                    128 / 255.0f);  // alpha stays linear
    Image16 height(1, 1, 1, 65535);
    EXPECT_FLOAT_EQ(texel(make_texture(height), 0, 0, 0).x(), 1.0f);
    ImageF depth(2, 1, 1, 0.25f);
    depth.pixels[1] = 0.75f;
    MipTexture floats = make_texture(depth);
    EXPECT_FLOAT_EQ(texel(floats, 0, 1, 0).x(), 0.75f);
    EXPECT_FLOAT_EQ(texel(floats, 1, 0, 0).x(), 0.5f);  // float mips are exact averages
    // sRGB mips average in linear space: black and white make 0.5 linear, not 0.5 encoded.
    Image8 pair(2, 1, 4, 255);
    pair.pixels[0] = pair.pixels[1] = pair.pixels[2] = 0;
    EXPECT_NEAR(texel(make_texture(pair, ColorSpace::srgb), 1, 0, 0).x(), 0.5f, 0.01f);
}

namespace {
// RGBA noise from the project's PCG32, the same on every machine.
Image8 seeded_image(int width, int height, std::uint64_t seed) {
    Image8 image(width, height, 4, 255);
    Pcg32 random(seed, 1);
    for (std::uint8_t& v : image.pixels) v = std::uint8_t(random.next_uint() >> 24);
    return image;
}
}  // namespace

// A face's colour and normal maps are sampled together: the same values as
// sampling each alone, whether they share a layout (one footprint for both)
// or not (other size, wrap or level: each its own).
TEST(Texture, SamplingTwoMapsTogetherEqualsSamplingEach) {
    const MipTexture color = make_texture(seeded_image(16, 8, 1), ColorSpace::srgb, Wrap::repeat);
    const MipTexture normal = make_texture(seeded_image(16, 8, 2), ColorSpace::linear, Wrap::repeat);
    const MipTexture other_size = make_texture(seeded_image(8, 8, 3), ColorSpace::linear, Wrap::repeat);
    const MipTexture other_wrap = make_texture(seeded_image(16, 8, 4), ColorSpace::linear, Wrap::clamp);
    int compared = 0;
    for (float lod : {0.0f, 0.4f, 1.0f, 2.7f, 9.0f})
        for (int i = 0; i < 40; ++i) {
            const Eigen::Vector2f uv(float(i) * 0.137f - 1.3f, float(i % 7) * 0.29f - 0.5f);
            for (const MipTexture* second : {&normal, &other_size, &other_wrap})
                for (float second_lod : {lod, lod + 0.5f}) {
                    const auto [a, b] = sample_both(color, lod, *second, second_lod, uv);
                    ASSERT_EQ(a, sample(color, uv, lod)) << "lod " << lod << ", sample " << i;
                    ASSERT_EQ(b, sample(*second, uv, second_lod)) << "lod " << second_lod << ", sample " << i;
                    ++compared;
                }
        }
    EXPECT_EQ(compared, 5 * 40 * 6);
}

// Repeat wraps a texel index of any sign into the texture, by a mask for
// power-of-two sizes and by a remainder for others: sampling whole periods
// away (either side) reads the same texels as sampling inside.
TEST(Texture, RepeatWrapsWholePeriodsForEverySize) {
    for (int width : {3, 4, 5, 8})
        for (Filter filter : {Filter::nearest, Filter::bilinear}) {
            Image8 image(width, 2, 4, 255);
            for (int i = 0; i < width * 2; ++i) image.pixels[std::size_t(i) * 4] = std::uint8_t(i * 25);
            MipTexture t = make_texture(image, ColorSpace::linear, Wrap::repeat);
            t.filter = filter;
            for (int x = 0; x < width; ++x)
                for (float offset : {0.0f, 0.25f}) {  // a texel centre, and a quarter texel right of it
                    const Eigen::Vector2f inside((float(x) + 0.5f + offset) / float(width), 0.25f);
                    const Eigen::Vector4f expected = sample(t, inside);
                    for (float periods : {-7.0f, -2.0f, -1.0f, 1.0f, 3.0f})
                        EXPECT_NEAR(sample(t, inside + Eigen::Vector2f(periods, 0)).x(), expected.x(), 1e-5f)
                            << "width " << width << ", texel " << x << ", periods " << periods;
                }
        }
}

// Four lanes sampled at once read what each lane's uv and level read alone:
// bit for bit, for both maps, at levels below 0, between levels, past the
// last one, at uvs far outside the texture and at non-finite ones, repeated
// (sizes a power of two or not) or clamped, for every filter.
TEST(Texture, SamplingInLanesEqualsSamplingEachLane) {
    Pcg32 random(7, 2);
    auto next = [&] { return float(random.uniform()); };
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    int compared = 0;
    for (auto [width, height] : {std::pair{16, 8}, std::pair{12, 5}})
        for (Wrap wrap : {Wrap::repeat, Wrap::clamp})
            for (Filter filter : {Filter::nearest, Filter::bilinear, Filter::trilinear}) {
                MipTexture color = make_texture(seeded_image(width, height, 1), ColorSpace::srgb, wrap);
                MipTexture normal = make_texture(seeded_image(width, height, 2), ColorSpace::linear, wrap);
                color.filter = normal.filter = filter;
                for (int group = 0; group < 200; ++group) {
                    FloatLanes u, v, lod;
                    for (int j = 0; j < lane_count; ++j) {
                        u[j] = (next() - 0.5f) * (group % 5 == 0 ? 2e6f : 6.0f);
                        v[j] = (next() - 0.3f) * 3.0f;
                        lod[j] = next() * 7.0f - 1.5f;
                        if (group % 7 == 0) lod[j] = float(int(lod[j]));  // on a level: one level read
                    }
                    if (group == 1) {
                        u[1] = nan;
                        v[2] = inf;
                        lod[3] = nan;
                    }
                    const int count = 1 + group % lane_count;
                    Vector4Lanes from_color{}, from_normal{};
                    sample_both(color, normal, u, v, lod, count, from_color, from_normal);
                    for (int j = 0; j < count; ++j) {
                        const auto [expected_color, expected_normal] =
                            sample_both(color, lod[j], normal, lod[j], {u[j], v[j]});
                        const FloatLanes* lanes_color[4] = {&from_color.x, &from_color.y, &from_color.z,
                                                            &from_color.w};
                        const FloatLanes* lanes_normal[4] = {&from_normal.x, &from_normal.y, &from_normal.z,
                                                             &from_normal.w};
                        for (int c = 0; c < 4; ++c) {
                            ASSERT_EQ(std::bit_cast<std::uint32_t>((*lanes_color[c])[j]),
                                      std::bit_cast<std::uint32_t>(expected_color[c]))
                                << width << "x" << height << ", group " << group << ", lane " << j
                                << ", channel " << c;
                            ASSERT_EQ(std::bit_cast<std::uint32_t>((*lanes_normal[c])[j]),
                                      std::bit_cast<std::uint32_t>(expected_normal[c]))
                                << width << "x" << height << ", group " << group << ", lane " << j
                                << ", channel " << c;
                        }
                        ++compared;
                    }
                }
            }
    EXPECT_EQ(compared, 2 * 2 * 3 * 500);
}
