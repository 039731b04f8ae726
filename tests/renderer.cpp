#include "renderer/renderer.h"

#include "golden.h"
#include "render_scene.h"
#include "renderer/exr_io.h"
#include "renderer/overlays.h"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace boxlod;

// Golden images are compared byte for byte. To regenerate them after an
// intended change: BOXLOD_UPDATE_GOLDEN=1 ctest -R Golden, then commit the
// PNGs with the reason in the commit message.
namespace {

void expect_golden(const Image8& image, const std::string& name) { test::expect_golden(image, name); }

Frame render_scene(const test::RenderScene& scene, const RenderSettings& settings, int width = 96, int height = 72) {
    Frame frame = make_frame(width, height, {1, 1, 1});
    render(scene.batches, settings, frame);
    return frame;
}

}  // namespace

TEST(RendererGolden, EachRenderMode) {
    auto scene = test::make_render_scene();
    for (RenderMode mode : {RenderMode::untextured, RenderMode::normal, RenderMode::parallax, RenderMode::pom, RenderMode::albedo}) {
        RenderSettings settings = scene->settings;
        settings.mode = mode;
        expect_golden(frame_to_srgb8(render_scene(*scene, settings)), std::string("renderer_") + render_mode_name(mode));
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
    left.mode = RenderMode::untextured, left.scissor_x1 = 48;
    right.mode = RenderMode::parallax, right.scissor_x0 = 48;
    render(scene->batches, left, split);
    render(scene->batches, right, split);
    draw_divider(split, 48, {0, 0, 0});
    expect_golden(frame_to_srgb8(split), "renderer_split_view");
}

TEST(Renderer, ModesDifferFromEachOther) {
    auto scene = test::make_render_scene();
    std::vector<std::vector<std::uint8_t>> images;
    for (RenderMode mode : {RenderMode::untextured, RenderMode::normal, RenderMode::parallax, RenderMode::pom, RenderMode::albedo}) {
        RenderSettings settings = scene->settings;
        settings.mode = mode;
        images.push_back(frame_to_srgb8(render_scene(*scene, settings)).pixels);
    }
    for (std::size_t i = 0; i < images.size(); ++i)
        for (std::size_t j = i + 1; j < images.size(); ++j) EXPECT_NE(images[i], images[j]) << i << " vs " << j;
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

TEST(Renderer, ScissorLeavesOtherPixelsUntouched) {
    auto scene = test::make_render_scene();
    RenderSettings settings = scene->settings;
    settings.scissor_x0 = 10, settings.scissor_x1 = 20, settings.scissor_y0 = 5, settings.scissor_y1 = 60;
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
    settings.camera.left = -2, settings.camera.right = 2, settings.camera.bottom = -2, settings.camera.top = 2;
    test::RenderScene& s = *scene;
    std::vector<Batch> floor_only{s.batches[0]};
    Frame frame = make_frame(40, 40, {0, 0, 0});
    render(floor_only, settings, frame);
    Image8 mask = coverage_mask(frame);
    for (std::uint8_t m : mask.pixels) ASSERT_EQ(m, 255);  // the floor fills the orthographic window exactly
    std::vector<float> depth = view_depth(frame, settings.camera);
    for (float d : depth) ASSERT_NEAR(d, 10, 1e-4);
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
