#include "renderer/shading.h"

#include "render_scene.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// A render mode the pipeline has never heard of: colour = the fragment's uv (blue: has none).
class UvShader : public Shader {
public:
    bool reads_uv() const override { return true; }
    ShadedPixel shade(const Surface&, Fragment& f) const override {
        if (!f.has_uv) return {{0, 0, 1}, f.normal};
        return {{f.uv.x(), f.uv.y(), 0}, f.normal};
    }
};

Frame render_with(const test::RenderScene& scene, const RenderSettings& settings) {
    Frame frame = make_frame(96, 72, {1, 1, 1});
    render(scene.batches, settings, frame);
    return frame;
}

}  // namespace

TEST(Shading, ANewShaderChangesColoursButNotWhichPixelsAreDrawn) {
    auto scene = test::make_render_scene();
    Frame normal = render_with(*scene, scene->settings);
    UvShader uv_shader;
    RenderSettings settings = scene->settings;
    settings.shader = &uv_shader;
    Frame uv = render_with(*scene, settings);
    EXPECT_EQ(coverage_mask(uv).pixels, coverage_mask(normal).pixels);
    EXPECT_EQ(uv.depth, normal.depth);
    int floor_pixels = 0, box_pixels = 0;
    for (std::size_t i = 0; i < uv.color.size(); ++i) {
        if (uv.color[i].w() == 0) continue;
        const Eigen::Vector4f& c = uv.color[i];
        if (c.z() == 1) {
            ++box_pixels;  // the untextured box
        } else {
            ++floor_pixels;  // the floor's uvs span [0, 2]
            EXPECT_TRUE(c.x() >= 0 && c.x() <= 2 && c.y() >= 0 && c.y() <= 2) << c.transpose();
        }
    }
    EXPECT_GT(floor_pixels, 1000);
    EXPECT_GT(box_pixels, 100);
}

TEST(Shading, EachModeHasItsShaderAndOnlyUntexturedSkipsUvs) {
    for (const EnumEntry<RenderMode>& mode : render_modes()) {
        RenderSettings settings;
        settings.mode = mode.value;
        std::unique_ptr<Shader> shader = make_shader(settings, {0, 0, 5});
        ASSERT_TRUE(shader) << mode.name;
        EXPECT_EQ(shader->reads_uv(), mode.value != RenderMode::untextured) << mode.name;
    }
}

TEST(Shading, AlbedoIsUnlitAndTheOtherModesAreLit) {
    Fragment f;
    f.position = {0, 0, 0};
    f.normal = f.geometric_normal = {0, 0, 1};
    Surface surface;
    surface.base_color = {0.5f, 0.25f, 1, 1};
    for (const EnumEntry<RenderMode>& mode : render_modes()) {
        RenderSettings settings;
        settings.mode = mode.value;
        settings.light.position = {0, 0, 10};
        Fragment fragment = f;
        ShadedPixel pixel = make_shader(settings, {0, 0, 5})->shade(surface, fragment);
        if (mode.value == RenderMode::albedo) {
            EXPECT_EQ(pixel.color, surface.base_color.head<3>());
        } else {
            // Light straight above: ambient + diffuse = 1 times albedo, plus the specular highlight.
            Eigen::Vector3f expected =
                surface.base_color.head<3>() + surface.specular * settings.light.specular;
            EXPECT_NEAR((pixel.color - expected).norm(), 0, 1e-5) << mode.name;
        }
    }
}

TEST(Shading, TwoSidedLightingTurnsTheFragmentTowardsTheEye) {
    Fragment f;
    f.position = {0, 0, 0};
    f.normal = f.geometric_normal = {0, 0, -1};  // facing away from the eye at +Z
    f.bitangent = {0, 1, 0};
    RenderSettings settings;
    settings.mode = RenderMode::untextured;
    ShadedPixel pixel = make_shader(settings, {0, 0, 5})->shade(Surface{}, f);
    EXPECT_EQ(pixel.normal, Eigen::Vector3f(0, 0, 1));
    EXPECT_EQ(f.bitangent, Eigen::Vector3f(0, -1, 0));
}

TEST(Shading, ColourAndNormalMapsOfDifferentSizesEachGetTheirOwnMipLevel) {
    auto patterned = [](int side, int seed) {
        Image8 image(side, side, 4);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            image.pixels[i] = std::uint8_t((i * 37 + seed) * 91 % 256);
        return image;
    };
    MipTexture color = make_texture(patterned(8, 1), ColorSpace::srgb);
    MipTexture normal_map = make_texture(patterned(4, 2), ColorSpace::linear);
    Surface surface;
    surface.color = &color;
    surface.normal = &normal_map;
    Fragment f;
    f.position = {0, 0, 0};
    f.normal = f.geometric_normal = {0, 0, 1};
    f.has_uv = true;
    f.uv = {0.3f, 0.6f};
    f.duv_dx = {0.25f, 0};  // 2 texels of the colour map per pixel (level 1), 1 of the normal map (level 0)
    f.duv_dy = {0, 0.25f};
    ASSERT_EQ(mip_level(color, f.duv_dx, f.duv_dy), 1);
    ASSERT_EQ(mip_level(normal_map, f.duv_dx, f.duv_dy), 0);
    RenderSettings settings;
    settings.mode = RenderMode::albedo;
    Fragment fragment = f;
    ShadedPixel pixel = make_shader(settings, {0, 0, 5})->shade(surface, fragment);
    EXPECT_EQ(pixel.color, sample(color, f.uv, 1).head<3>());
    Eigen::Vector4f texel = sample(normal_map, f.uv, 0);
    Eigen::Vector3f expected =
        Eigen::Vector3f(texel.x() * 2 - 1, texel.y() * 2 - 1, texel.z() * 2 - 1).normalized();
    EXPECT_EQ(pixel.normal, expected);
    EXPECT_NE(sample(normal_map, f.uv, 1), texel);  // so the normal map's level matters
}

// Parallax moves the lookup to the point of the map seen along the view ray:
// in the manual's uv units when the height map states no depth, in metres
// through the uv gradient when it does (docs/design.md: Rendering).
TEST(Shading, ParallaxOffsetsAreInUvOrInMetresAsTheHeightMapStates) {
    Image8 ramp(64, 64, 4, 255);  // red along u, green along v: the colour says where the lookup landed
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            ramp.at(x, y)[0] = std::uint8_t(x * 4);
            ramp.at(x, y)[1] = std::uint8_t(y * 4);
        }
    MipTexture color = make_texture(ramp, ColorSpace::linear);
    MipTexture height = make_texture(Image16(4, 4, 1, 16384));  // h = 0.25 everywhere
    Fragment f;
    f.position = {0, 0, 0};
    f.normal = f.geometric_normal = {0, 0, 1};
    f.tangent = {1, 0, 0};
    f.bitangent = {0, 1, 0};
    f.has_uv = true;
    f.uv = {0.5f, 0.5f};
    const UvGradient gradient{
        {0.5f, 0, 0}, {0, -0.25f, 0}};  // u = x / 2, v = -y / 4: v runs down the image, the bitangent up
    f.uv_gradient = &gradient;
    const Eigen::Vector3f eye(3, 2, 6);
    const Eigen::Vector3f view = eye.normalized();
    const float h = 16384.0f / 65535.0f;
    RenderSettings settings;
    settings.light.position = {0, 0, 10};
    auto shade_at = [&](RenderMode mode, float depth, const Eigen::Vector2f* uv) {
        Surface surface;
        surface.color = &color;
        surface.height = uv ? nullptr : &height;
        surface.height_depth = depth;
        Fragment fragment = f;
        if (uv) fragment.uv = *uv;
        settings.mode = mode;
        return make_shader(settings, eye)->shade(surface, fragment).color;
    };
    const Eigen::Vector2f per_metre(view.x() * 0.5f, -view.y() * 0.25f), in_uv(view.x(), -view.y());
    const float depth = 0.4f;
    struct Case {
        RenderMode mode;
        float depth;
        Eigen::Vector2f expected_uv;
    } cases[] = {
        {RenderMode::parallax, 0, f.uv + in_uv * (h * settings.parallax_scale + settings.parallax_bias)},
        {RenderMode::parallax, depth, f.uv + per_metre * ((h - 1) * depth)},  // offset limiting: no 1 / cos
        {RenderMode::pom, depth,
         f.uv + per_metre * ((h - 1) * depth / view.z())},  // the ray meets h at depth 0.75
    };
    const float tolerance = 2e-4f;  // the colour of a uv a rounding step away
    for (const Case& c : cases) {
        Eigen::Vector3f displaced = shade_at(c.mode, c.depth, nullptr),
                        expected = shade_at(RenderMode::normal, 0, &c.expected_uv);
        EXPECT_NEAR((displaced - expected).norm(), 0, tolerance)
            << render_mode_name(c.mode) << " depth " << c.depth;
        Eigen::Vector3f undisplaced = shade_at(RenderMode::normal, 0, &f.uv);
        EXPECT_GT((displaced - undisplaced).norm(), 10 * tolerance)
            << render_mode_name(c.mode) << " depth " << c.depth;
    }
    // Seen from behind (inside a box, through a cut-out), a metric height map
    // offsets nothing; one in uv units keeps the manual's offset.
    f.geometric_normal = f.normal = {0, 0, -1};
    f.bitangent = {0, -1, 0};
    for (RenderMode mode : {RenderMode::parallax, RenderMode::pom}) {
        EXPECT_EQ(shade_at(mode, depth, nullptr), shade_at(RenderMode::normal, 0, &f.uv))
            << render_mode_name(mode);
        EXPECT_NE(shade_at(mode, 0, nullptr), shade_at(RenderMode::normal, 0, &f.uv))
            << render_mode_name(mode);
    }
}
