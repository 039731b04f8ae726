#include "toolkit/metrics/shot.h"

#include "lod_scene.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/model/framing.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// The test building framed from a raised corner, one thread.
RenderSettings framing_settings(const DrawableModel& drawable) {
    const Framing framing = framing_of(drawable.drawable.bounds);
    RenderSettings settings;
    settings.camera = framed_camera(framing, {1, 1, 1}, framing_distance(framing, 45), 45);
    settings.light = light_for_camera(settings.camera);
    settings.threads = 1;
    return settings;
}

}  // namespace

// On white, the coverage is the pixels the model draws; nothing drawn, nothing covered.
TEST(Shot, CoversWhatTheModelDrawsOnWhite) {
    const std::unique_ptr<DrawableModel> drawable = make_drawable_model(test::lod_test_building());
    const RenderSettings settings = framing_settings(*drawable);
    const Shot shot = render_shot(drawable->drawable.batches, settings, 64, 48);
    ASSERT_EQ(shot.image.width, 64);
    ASSERT_EQ(shot.coverage.covered.size(), 64u * 48u);
    EXPECT_GT(covered_pixels(shot.coverage), 300u);
    EXPECT_LT(covered_pixels(shot.coverage), 64u * 48u);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            if (!shot.coverage.covered[std::size_t(y * 64 + x)]) {
                const std::uint8_t* p = shot.image.at(x, y);
                EXPECT_TRUE(p[0] == 255 && p[1] == 255 && p[2] == 255) << x << "," << y;
            }
    EXPECT_FALSE(shot.flip_reference.has_value());
    const Shot empty = render_shot({}, settings, 16, 16);
    EXPECT_EQ(covered_pixels(empty.coverage), 0u);
}

// Supersampled: the same size, more pixels covered (a pixel is where any of its 16 samples is), and
// pixels at the edges blended between the building's colour and white.
TEST(Shot, SupersampledBlendsEdgesAndCoversAnyPixelASampleCovers) {
    const std::unique_ptr<DrawableModel> drawable = make_drawable_model(test::lod_test_building());
    const RenderSettings settings = framing_settings(*drawable);
    const Shot one = render_shot(drawable->drawable.batches, settings, 64, 48);
    const Shot four = render_shot(drawable->drawable.batches, settings, 64, 48, 4);
    ASSERT_EQ(four.image.width, 64);
    ASSERT_EQ(four.image.height, 48);
    EXPECT_GT(covered_pixels(four.coverage), covered_pixels(one.coverage));
    int blended = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            const std::uint8_t* p = four.image.at(x, y);
            if (four.coverage.covered[std::size_t(y * 64 + x)] &&
                !one.coverage.covered[std::size_t(y * 64 + x)])
                blended += p[0] > 128 && p[0] < 255;  // part building, part white
        }
    EXPECT_GT(blended, 10);
}
