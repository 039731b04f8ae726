#include "renderer/renderer.h"

#include "base/memory_budget.h"
#include "golden.h"
#include "render_scene.h"
#include "renderer/exr_io.h"
#include "renderer/overlays.h"
#include "renderer/shading.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <stdexcept>

#include <cstdlib>
#include <cstring>

using namespace boxlod;

// Golden images are compared byte for byte. To regenerate them after an
// intended change: BOXLOD_UPDATE_GOLDEN=1 ctest -R Golden, then commit the
// PNGs with the reason in the commit message.
namespace {

void expect_golden(const Image8& image, const std::string& name) { test::expect_golden(image, name); }

Frame render_scene(const test::RenderScene& scene, const RenderSettings& settings, int width = 96,
                   int height = 72) {
    Frame frame = make_frame(width, height, {1, 1, 1});
    render(scene.batches, settings, frame);
    return frame;
}

}  // namespace

TEST(RendererGolden, EachRenderMode) {
    auto scene = test::make_render_scene();
    for (RenderMode mode : {RenderMode::untextured, RenderMode::normal, RenderMode::parallax, RenderMode::pom,
                            RenderMode::albedo}) {
        RenderSettings settings = scene->settings;
        settings.mode = mode;
        expect_golden(frame_to_srgb8(render_scene(*scene, settings)),
                      std::string("renderer_") + render_mode_name(mode));
    }
}

TEST(RendererGolden, WireframeAxesAndSplitView) {
    auto scene = test::make_render_scene();
    RenderSettings settings = scene->settings;
    settings.wireframe = true;
    Frame frame = render_scene(*scene, settings);
    draw_axes(frame, settings.camera, {0, 0, 0}, 1.5f);
    expect_golden(frame_to_srgb8(frame), "renderer_wireframe_axes");

    // Split view: left half untextured, right half parallax.
    Frame split = make_frame(96, 72, {1, 1, 1});
    RenderSettings left = scene->settings, right = scene->settings;
    left.mode = RenderMode::untextured;
    left.scissor_x1 = 48;
    right.mode = RenderMode::parallax;
    right.scissor_x0 = 48;
    render(scene->batches, left, split);
    render(scene->batches, right, split);
    draw_divider(split, 48, {0, 0, 0});
    expect_golden(frame_to_srgb8(split), "renderer_split_view");
}

TEST(Renderer, ModesDifferFromEachOther) {
    auto scene = test::make_render_scene();
    std::vector<std::vector<std::uint8_t>> images;
    for (RenderMode mode : {RenderMode::untextured, RenderMode::normal, RenderMode::parallax, RenderMode::pom,
                            RenderMode::albedo}) {
        RenderSettings settings = scene->settings;
        settings.mode = mode;
        images.push_back(frame_to_srgb8(render_scene(*scene, settings)).pixels);
    }
    for (std::size_t i = 0; i < images.size(); ++i)
        for (std::size_t j = i + 1; j < images.size(); ++j)
            EXPECT_NE(images[i], images[j]) << i << " vs " << j;
}

// maps_drawn says which maps each mode's picture reads (what a mode's cost
// counts): taking a map away changes the picture exactly where it says so.
TEST(Renderer, EachModesPictureReadsTheMapsItsCostCounts) {
    auto scene = test::make_render_scene();
    for (const EnumEntry<RenderMode>& mode : render_modes()) {
        RenderSettings settings = scene->settings;
        settings.mode = mode.value;
        const std::vector<std::uint8_t> all = frame_to_srgb8(render_scene(*scene, settings)).pixels;
        const MapsDrawn drawn = maps_drawn(mode.value);
        for (auto [map, read] : {std::pair{&Surface::color, drawn.color},
                                 {&Surface::normal, drawn.normal},
                                 {&Surface::height, drawn.height}}) {
            std::vector<Batch> without = scene->batches;
            without[0].surface.*map = nullptr;  // the floor's
            Frame frame = make_frame(96, 72, {1, 1, 1});
            render(without, settings, frame);
            EXPECT_EQ(frame_to_srgb8(frame).pixels != all, read) << mode.name;
        }
    }
}

TEST(Renderer, OutputIsIdenticalForAnyThreadCount) {
    auto scene = test::make_render_scene();
    RenderSettings settings = scene->settings;
    settings.mode = RenderMode::pom;
    settings.wireframe = true;
    settings.threads = 1;
    Frame reference = render_scene(*scene, settings, 301, 203);
    for (int threads : {2, 3, 8}) {
        settings.threads = threads;
        Frame frame = render_scene(*scene, settings, 301, 203);
        EXPECT_EQ(frame.color, reference.color) << threads << " threads";
        EXPECT_EQ(frame.depth, reference.depth) << threads << " threads";
    }
}

// A batch's translation places its mesh as moving the mesh would: the scene
// translated, seen by a camera and lit by a light translated with it, is the
// picture of the scene in place (up to rounding on a few edge pixels).
TEST(Renderer, ATranslatedBatchIsDrawnAndLitWhereItIsPlaced) {
    auto scene = test::make_render_scene();
    RenderSettings settings = scene->settings;
    settings.light.position = {0.8f, 1.2f, 0.5f};  // near: lighting depends on where fragments are
    Frame in_place = render_scene(*scene, settings);
    const Eigen::Vector3f t(37, -5, 112);
    for (Batch& batch : scene->batches) batch.translation = t;
    settings.camera.position += t;
    settings.camera.target += t;
    settings.light.position += t;
    Frame moved = render_scene(*scene, settings);
    auto pixels_differing = [&](const Frame& frame) {
        int count = 0;
        for (std::size_t i = 0; i < frame.color.size(); ++i)
            count += (frame.color[i] - in_place.color[i]).cwiseAbs().maxCoeff() > 0.02f;
        return count;
    };
    EXPECT_LT(pixels_differing(moved), int(in_place.color.size() / 200));
    settings.light.position -= t;  // the light left behind: the lighting must change
    EXPECT_GT(pixels_differing(render_scene(*scene, settings)), int(in_place.color.size() / 4));
    for (Batch& batch : scene->batches) batch.translation = Eigen::Vector3f::Zero();
    EXPECT_GT(pixels_differing(render_scene(*scene, settings)),
              int(in_place.color.size() / 4));  // not drawn in view
}

// A city draws tens of thousands of small batches: they share chunks of
// triangles, and each is drawn as if it were alone.
TEST(Renderer, TensOfThousandsOfSmallBatchesAreAllDrawn) {
    Mesh triangle;
    triangle.positions = {{-0.4f, -0.4f, 0}, {0.4f, -0.4f, 0}, {0, 0.4f, 0}};
    triangle.indices = {0, 1, 2};
    const int side = 150;  // 22,500 batches, one triangle each, one per pixel block
    std::vector<Batch> batches;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            batches.push_back({&triangle, {}});
            batches.back().translation = {float(x) - side / 2.0f + 0.5f, float(y) - side / 2.0f + 0.5f, 0};
        }
    RenderSettings settings;
    settings.mode = RenderMode::untextured;
    settings.camera.orthographic = true;
    settings.camera.position = {0, 0, 10};
    settings.camera.target = {0, 0, 0};
    settings.camera.left = settings.camera.bottom = -side / 2.0f;
    settings.camera.right = settings.camera.top = side / 2.0f;
    Frame frame = make_frame(side * 4, side * 4, {1, 1, 1});
    render(batches, settings, frame);
    int drawn = 0;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            drawn += frame.color[std::size_t((4 * y + 2) * frame.width + 4 * x + 2)].w() > 0;
    EXPECT_EQ(drawn, side * side);
}

TEST(Renderer, ARenderOverAnEarlierOneFromItsDepthIsBothInOne) {
    // The box first, then the floor behind it and a blended pane with the depth
    // test from the box's depth: the picture of one render of all three.
    auto scene = test::make_render_scene();
    const Batch& floor = scene->batches[0];
    const Batch& box = scene->batches[1];
    Batch pane = box;
    pane.surface.alpha_mode = AlphaMode::blend;
    pane.surface.base_color = {0.2f, 0.4f, 0.9f, 0.5f};
    Mesh moved = scene->box;
    for (Eigen::Vector3f& p : moved.positions) p += Eigen::Vector3f(0.4f, 0.2f, 0.5f);
    pane.mesh = &moved;
    for (RenderMode mode : {RenderMode::untextured, RenderMode::pom}) {
        RenderSettings settings = scene->settings;
        settings.mode = mode;
        Frame both = make_frame(150, 110, {1, 1, 1});
        render({box, floor, pane}, settings, both);
        Frame layered = make_frame(150, 110, {1, 1, 1});
        render({box}, settings, layered);
        settings.depth_from_frame = true;
        render({floor, pane}, settings, layered);
        EXPECT_EQ(layered.color, both.color) << render_mode_name(mode);
        EXPECT_EQ(layered.depth, both.depth);
        EXPECT_EQ(layered.normal, both.normal);
        // From +infinity instead, the floor is drawn over the box.
        settings.depth_from_frame = false;
        Frame over = make_frame(150, 110, {1, 1, 1});
        render({box}, settings, over);
        render({floor, pane}, settings, over);
        EXPECT_NE(over.color, both.color);
    }
}

TEST(Renderer, ScissorLeavesOtherPixelsUntouched) {
    auto scene = test::make_render_scene();
    RenderSettings settings = scene->settings;
    settings.scissor_x0 = 10;
    settings.scissor_x1 = 20;
    settings.scissor_y0 = 5;
    settings.scissor_y1 = 60;
    Frame frame = render_scene(*scene, settings);
    int covered = 0;
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            bool inside = x >= 10 && x < 20 && y >= 5 && y < 60;
            float alpha = frame.color[std::size_t(y) * frame.width + x].w();
            if (!inside) {
                ASSERT_EQ(alpha, 0) << x << "," << y;
            }
            covered += alpha > 0;
        }
    EXPECT_GT(covered, 100);
}

TEST(Renderer, CoverageAndDepthMatchTheGeometry) {
    auto scene = test::make_render_scene();
    RenderSettings settings = scene->settings;
    settings.camera = camera_at_position({0, 1, 0}, {0, 0, 0}, 10, 30, 5);  // straight down
    settings.camera.orthographic = true;
    settings.camera.left = -2;
    settings.camera.right = 2;
    settings.camera.bottom = -2;
    settings.camera.top = 2;
    test::RenderScene& s = *scene;
    std::vector<Batch> floor_only{s.batches[0]};
    Frame frame = make_frame(40, 40, {0, 0, 0});
    render(floor_only, settings, frame);
    Image8 mask = coverage_mask(frame);
    for (std::uint8_t m : mask.pixels) ASSERT_EQ(m, 255);  // the floor fills the orthographic window exactly
    std::vector<float> depth = view_depth(frame, settings.camera);
    for (float d : depth) ASSERT_NEAR(d, 10, 1e-4);
}

namespace {

// A quad filling the orthographic window of `alpha_scene_settings`, at height z (nearer the camera for larger
// z).
Mesh window_quad(float z) {
    Mesh quad;
    quad.positions = {{-2, -2, z}, {2, -2, z}, {2, 2, z}, {-2, 2, z}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    return quad;
}

// Unlit (albedo mode), orthographic down -z: each pixel's colour is exactly the composite of the albedos.
RenderSettings alpha_scene_settings() {
    RenderSettings settings;
    settings.mode = RenderMode::albedo;
    settings.camera.orthographic = true;
    settings.camera.position = {0, 0, 10};
    settings.camera.target = {0, 0, 0};
    settings.camera.left = -1;
    settings.camera.right = 1;
    settings.camera.bottom = -1;
    settings.camera.top = 1;
    return settings;
}

Surface flat_surface(const Eigen::Vector4f& color, AlphaMode mode) {
    Surface surface;
    surface.base_color = color;
    surface.alpha_mode = mode;
    return surface;
}

Eigen::Vector4f centre_pixel(const std::vector<Batch>& batches, int threads = 0) {
    RenderSettings settings = alpha_scene_settings();
    settings.threads = threads;
    Frame frame = make_frame(8, 8, {0, 1, 0});
    render(batches, settings, frame);
    for (const Eigen::Vector4f& pixel : frame.color) EXPECT_EQ(pixel, frame.color[0]);  // uniform
    return frame.color[27];
}

}  // namespace

TEST(RendererAlpha, BlendIsSourceOverTheOpaqueSurfaceBehind) {
    Mesh wall = window_quad(0), glass = window_quad(1);
    std::vector<Batch> batches{
        {&glass, flat_surface({0, 0, 1, 0.25f}, AlphaMode::blend)},  // submitted first, drawn last
        {&wall, flat_surface({1, 0, 0, 1}, AlphaMode::opaque)}};
    EXPECT_EQ(centre_pixel(batches), Eigen::Vector4f(0.75f, 0, 0.25f, 1));
    // Over the green background alone: alpha is the coverage.
    std::vector<Batch> glass_only{batches[0]};
    EXPECT_EQ(centre_pixel(glass_only), Eigen::Vector4f(0, 0.75f, 0.25f, 0.25f));
    // Behind the wall, the glass is hidden.
    Mesh behind = window_quad(-1);
    std::vector<Batch> hidden{{&behind, batches[0].surface}, batches[1]};
    EXPECT_EQ(centre_pixel(hidden), Eigen::Vector4f(1, 0, 0, 1));
}

TEST(RendererAlpha, BlendedTrianglesCompositeBackToFrontWhateverTheirOrder) {
    Mesh far = window_quad(0), near = window_quad(1);
    Batch red{&far, flat_surface({1, 0, 0, 0.5f}, AlphaMode::blend)},
        blue{&near, flat_surface({0, 0, 1, 0.5f}, AlphaMode::blend)};
    // Blue over (red over green): 0.5 blue + 0.25 red + 0.25 green; coverage 0.75.
    Eigen::Vector4f expected(0.25f, 0.25f, 0.5f, 0.75f);
    EXPECT_EQ(centre_pixel({red, blue}), expected);
    EXPECT_EQ(centre_pixel({blue, red}), expected);
    for (int threads : {1, 2, 3})
        EXPECT_EQ(centre_pixel({blue, red}, threads), expected) << threads << " threads";
}

TEST(RendererAlpha, MaskDropsFragmentsBelowTheCutoffAndOpaqueIgnoresAlpha) {
    Mesh wall = window_quad(0), front = window_quad(1);
    Batch background{&wall, flat_surface({1, 0, 0, 1}, AlphaMode::opaque)};
    Batch masked{&front, flat_surface({0, 0, 1, 0.3f}, AlphaMode::mask)};
    masked.surface.alpha_cutoff = 0.25f;
    EXPECT_EQ(centre_pixel({background, masked}), Eigen::Vector4f(0, 0, 1, 1));  // 0.3 >= 0.25: drawn
    masked.surface.alpha_cutoff = 0.5f;
    EXPECT_EQ(centre_pixel({background, masked}), Eigen::Vector4f(1, 0, 0, 1));  // 0.3 < 0.5: dropped
    masked.surface.alpha_mode = AlphaMode::opaque;
    EXPECT_EQ(centre_pixel({background, masked}), Eigen::Vector4f(0, 0, 1, 1));
}

TEST(RendererAlpha, GlassLeavesTheNearestDepthAndNormal) {
    Mesh wall = window_quad(0), glass = window_quad(1);
    std::vector<Batch> batches{{&wall, flat_surface({1, 0, 0, 1}, AlphaMode::opaque)},
                               {&glass, flat_surface({0, 0, 1, 0.25f}, AlphaMode::blend)}};
    Frame opaque_only = make_frame(8, 8, {0, 0, 0}), both = opaque_only;
    render({batches[0]}, alpha_scene_settings(), opaque_only);
    render(batches, alpha_scene_settings(), both);
    EXPECT_LT(both.depth[27], opaque_only.depth[27]);  // the glass is nearer
    EXPECT_EQ(both.normal[27], Eigen::Vector3f(0, 0, 1));
}

TEST(ExrIo, WritesAReadableFileAtomically) {
    auto folder = test::scratch_folder("exr");
    auto scene = test::make_render_scene();
    Frame frame = render_scene(*scene, scene->settings);
    write_exr((folder / "a.exr").string(), frame, scene->settings.camera);
    write_exr((folder / "b.exr").string(), frame, scene->settings.camera);
    std::string a = test::read_text(folder / "a.exr");
    EXPECT_EQ(a.substr(0, 4), std::string("\x76\x2f\x31\x01", 4));  // OpenEXR magic number
    EXPECT_EQ(a, test::read_text(folder / "b.exr"));
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) files += entry.is_regular_file();
    EXPECT_EQ(files, 2u);
}

namespace {

// Writes the uv gradient the pipeline hands over: colour = du/dposition, normal = dv/dposition.
class UvGradientShader : public Shader {
public:
    bool reads_uv() const override { return true; }
    ShadedPixel shade(const Surface&, Fragment& f) const override {
        if (!f.uv_gradient) return {Eigen::Vector3f::Zero(), Eigen::Vector3f::Zero()};
        return {f.uv_gradient->du_dposition, f.uv_gradient->dv_dposition};
    }
};

}  // namespace

// A slanted quad with a sheared, anisotropic mapping: every pixel gets the
// triangle's uv gradient in world space, exactly where the height map states
// its depth (a metric parallax offset maps through it), and none elsewhere.
TEST(Renderer, FragmentsCarryTheUvGradientWhereTheHeightMapStatesItsDepth) {
    const Eigen::Matrix3f tilt =
        Eigen::AngleAxisf(0.5f, Eigen::Vector3f(1, 2, 0).normalized()).toRotationMatrix();
    // uv = M (x, y) in the quad's plane before the tilt: u = 0.25 x + 0.1 y, v = -0.5 y.
    Eigen::Matrix<float, 2, 3> m;
    m << 0.25f, 0.1f, 0, 0, -0.5f, 0;
    Mesh quad;
    for (const Eigen::Vector3f& corner : {Eigen::Vector3f(-1, -1, 0), Eigen::Vector3f(1, -1, 0),
                                          Eigen::Vector3f(1, 1, 0), Eigen::Vector3f(-1, 1, 0)}) {
        quad.positions.push_back(tilt * corner);
        quad.uvs.push_back(m * corner);
    }
    quad.indices = {0, 1, 2, 0, 2, 3};
    MipTexture height = make_texture(Image16(2, 2, 1, 65535));
    Surface surface;
    surface.height = &height;
    UvGradientShader shader;
    RenderSettings settings;
    settings.shader = &shader;
    settings.camera.position = {0.5f, 0.3f, 4};
    const Eigen::Vector3f du = tilt * m.row(0).transpose(), dv = tilt * m.row(1).transpose();
    for (float depth : {0.0f, 0.3f}) {
        surface.height_depth = depth;
        Frame frame = make_frame(32, 32, {1, 1, 1});
        render({{&quad, surface}}, settings, frame);
        int covered = 0;
        for (std::size_t i = 0; i < frame.color.size(); ++i) {
            if (frame.color[i].w() == 0) continue;
            ++covered;
            EXPECT_NEAR((frame.color[i].head<3>() - (depth > 0 ? du : Eigen::Vector3f::Zero())).norm(), 0,
                        1e-5)
                << i;
            EXPECT_NEAR((frame.normal[i] - (depth > 0 ? dv : Eigen::Vector3f::Zero())).norm(), 0, 1e-5) << i;
        }
        EXPECT_GT(covered, 200);
    }
}

namespace {

// A render mode's shading, one pixel at a time: takes_lanes() false sends the
// pipeline's scalar path (make_fragment), true its lanes with the default
// shade_lanes (each lane through shade()).
class OnePixelAtATime : public Shader {
public:
    OnePixelAtATime(const Shader& inner, bool scalar_fragments)
        : inner_(inner), scalar_fragments_(scalar_fragments) {}
    bool reads_uv() const override { return inner_.reads_uv(); }
    bool takes_lanes() const override { return !scalar_fragments_; }
    ShadedPixel shade(const Surface& s, Fragment& f) const override { return inner_.shade(s, f); }

private:
    const Shader& inner_;
    bool scalar_fragments_;
};

// A wavy grid of small triangles over the floor, so that a lane group holds
// several triangles; some vertex normals are zero (the geometric normal
// stands in). With uvs, some triangles' uvs are degenerate (no uv frame);
// with tangents too, their w changes sign across the grid.
Mesh wavy_grid(int cells, bool with_normals, bool with_uvs = false, bool with_tangents = false) {
    Mesh mesh;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            float x = float(i) / float(cells) * 3 - 1.5f, z = float(j) / float(cells) * 3 - 1.5f;
            mesh.positions.emplace_back(x, 0.1f + 0.05f * std::sin(x * 9) * std::cos(z * 7), z);
            if (with_normals)
                mesh.normals.push_back(
                    (i + j) % 7 == 0 ? Eigen::Vector3f::Zero()
                                     : Eigen::Vector3f(std::sin(x * 5), 2, std::cos(z * 3)).normalized());
            if (with_uvs)
                mesh.uvs.emplace_back(i % 5 == 0 ? 0.0f : x * 1.7f + z * 0.3f,
                                      (i + j) % 5 == 0 ? 0.0f : z * 2.1f);
            if (with_tangents)
                mesh.tangents.emplace_back(std::cos(z * 4), 0.3f * x, std::sin(z * 4),
                                           i % 3 == 0 ? -1.0f : 1.0f);
        }
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            std::uint32_t a = std::uint32_t(j * (cells + 1) + i), b = a + 1, c = a + std::uint32_t(cells) + 1,
                          d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    return mesh;
}

bool same_bits(const Frame& a, const Frame& b) {
    auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
    };
    return same(a.color, b.color) && same(a.depth, b.depth) && same(a.normal, b.normal);
}

}  // namespace

// Opaque pixels are made four at a time in SIMD lanes, and untextured ones
// shaded so (docs/performance.md: Lanes); each must have the bits of the
// one-pixel path in every mode, with clipped triangles, surfaces seen from
// behind, meshes with and without normals, uvs and tangents, degenerate uvs,
// height maps with a stated depth, and several surfaces in one group of lanes.
TEST(Renderer, LanesGiveTheBitsOfOnePixelAtATime) {
    auto scene = test::make_render_scene();
    Mesh with_normals = wavy_grid(23, true), without_normals = wavy_grid(17, false);
    Mesh with_tangents = wavy_grid(19, true, true, true), with_uvs = wavy_grid(13, false, true);
    for (Eigen::Vector3f& p : with_normals.positions)
        p.y() += 0.05f;  // a little apart, interleaved with the floor
    for (Eigen::Vector3f& p : with_tangents.positions) p.y() += 0.02f;
    for (Eigen::Vector3f& p : with_uvs.positions) p.y() -= 0.03f;
    std::vector<Batch> batches = scene->batches;
    batches.push_back({&with_normals, {}});
    batches.back().surface.base_color = {0.2f, 0.7f, 0.4f, 0.6f};
    batches.back().surface.specular = {0.5f, 0.4f, 0.1f};
    batches.push_back({&without_normals, {}});
    batches.back().surface.shininess = 64;
    batches.push_back({&with_tangents, batches[0].surface});
    batches.back().surface.height_depth = 0.05f;  // metric parallax: fragments carry the uv gradient
    batches.push_back({&with_uvs, batches[0].surface});
    batches.back().surface.normal = nullptr;
    batches.back().translation = {0.05f, 0, -0.04f};  // drawn elsewhere: lit where it is drawn

    RenderSettings settings = scene->settings;
    std::vector<Camera> cameras{settings.camera,
                                camera_at_position({1, 0.4f, 0.2f}, {0, 0.2f, 0}, 1.2f, 70, 3)};
    cameras[1].near_plane = 0.5f;  // cuts the floor and the grids: clipped triangles
    cameras.push_back(cameras[0]);
    cameras[2].position = {0.1f, 0.55f, -0.05f};  // inside the box: every face seen from behind
    cameras.push_back(cameras[0]);
    cameras[3].orthographic = true;
    int drawn = 0;
    for (const auto& mode : render_modes())
        for (std::size_t k = 0; k < cameras.size(); ++k)
            for (bool wireframe : {false, true}) {
                if (wireframe && mode.value != RenderMode::untextured && mode.value != RenderMode::normal)
                    continue;
                settings.mode = mode.value;
                settings.camera = cameras[k];
                settings.wireframe = wireframe;
                settings.shader = nullptr;
                Frame lanes = make_frame(131, 97, {1, 1, 1});
                render(batches, settings, lanes);
                Eigen::Vector3f eye =
                    settings.camera.position;  // an orthographic eye as the pipeline places it
                if (settings.camera.orthographic) eye -= (settings.camera.target - eye).normalized() * 1e6f;
                std::unique_ptr<Shader> shader = make_shader(settings, eye);
                for (bool scalar_fragments : {true, false}) {
                    OnePixelAtATime one(*shader, scalar_fragments);
                    settings.shader = &one;
                    Frame reference = make_frame(131, 97, {1, 1, 1});
                    render(batches, settings, reference);
                    EXPECT_TRUE(same_bits(lanes, reference))
                        << mode.name << ", camera " << k << (wireframe ? ", wireframe" : "")
                        << (scalar_fragments ? ", scalar fragments" : ", lane fragments");
                }
                for (const Eigen::Vector4f& c : lanes.color) drawn += c.w() > 0;
            }
    EXPECT_GT(drawn, 131 * 97 * int(render_modes().size()));  // the views are not empty
}

TEST(Renderer, AFrameOverTheMemoryBudgetIsRefusedBeforeItIsAllocated) {
    set_memory_budget(32.0 * 512 * 512);  // a frame is 32 bytes a pixel
    EXPECT_NO_THROW(make_frame(512, 512, {0, 0, 0}));
    EXPECT_THROW(make_frame(513, 512, {0, 0, 0}), InputError);
    set_memory_budget(0);
}

TEST(Renderer, DownsampleAveragesBlocksOfColourAndCoverage) {
    Frame frame = make_frame(4, 2, {0, 0, 0});
    for (int x = 0; x < 4; ++x) {
        frame.color[std::size_t(x)] = Eigen::Vector4f(float(x), 0, 1, x < 2 ? 1.f : 0.f);
        frame.color[std::size_t(4 + x)] = Eigen::Vector4f(float(x), 1, 1, x == 0 ? 1.f : 0.f);
    }
    const Frame half = downsample(frame, 2);
    ASSERT_EQ(half.width, 2);
    ASSERT_EQ(half.height, 1);
    EXPECT_EQ(half.color[0], Eigen::Vector4f(0.5f, 0.5f, 1, 0.75f));  // three of four samples covered
    EXPECT_EQ(half.color[1], Eigen::Vector4f(2.5f, 0.5f, 1, 0));
    EXPECT_TRUE(half.depth.empty());
    EXPECT_THROW(downsample(frame, 3), std::invalid_argument);  // 3 does not divide 4
    EXPECT_THROW(downsample(frame, 0), std::invalid_argument);
}
