#include "experiments/sweep/sweep_shots.h"

#include "lod_scene.h"
#include "toolkit/drawing/drawable.h"

#include <gtest/gtest.h>

namespace boxlod {
namespace {

TEST(SweepShots, ChoiceErrorTakesFlipThenSsimRmsePsnrIou) {
    EXPECT_EQ(choice_error({Metric::psnr, Metric::ssim, Metric::flip}, {30, 0.75, 0.0625}), 0.0625);
    EXPECT_EQ(choice_error({Metric::psnr, Metric::ssim, Metric::rmse}, {30, 0.75, 4}), 0.25);
    EXPECT_EQ(choice_error({Metric::iou, Metric::psnr, Metric::rmse}, {0.5, 30, 4}), 4);
    EXPECT_EQ(choice_error({Metric::iou, Metric::psnr}, {0.5, 30}), -30);
    EXPECT_EQ(choice_error({Metric::iou}, {0.75}), 0.25);
    EXPECT_EQ(choice_error({}, {}), 0);
}

// A view's shot against itself (FLIP from its prepared half) measures
// nothing; against another view it measures a difference.
TEST(SweepShots, AShotMatchesItselfAndNotAnotherView) {
    const Model building = test::lod_test_building();
    const std::unique_ptr<DrawableModel> drawable = make_drawable_model(building);
    const Framing framing = framing_of(drawable->drawable.bounds);
    SweepConfig config;
    config.metrics = {Metric::rmse, Metric::flip};
    auto shot = [&](const std::string& view) {
        return render_shot(drawable->drawable.batches,
                           view_settings(framing, view, 1, RenderMode::normal, config.lod, 1), 64, 48);
    };
    Shot reference = shot("+X+Y+Z");
    reference.flip_reference = prepare_flip_reference(reference.image, config.pixels_per_degree, 1);
    EXPECT_GT(covered_pixels(reference.coverage), 300u);
    const Metrics same = compare_shots(config, reference, shot("+X+Y+Z"), true, 1);
    EXPECT_EQ(same.values, (std::vector<std::string>{"0", "0"}));
    EXPECT_EQ(same.error, 0);
    EXPECT_EQ(same.heatmap.width, 64);
    const Metrics other = compare_shots(config, reference, shot("-X+Y+Z"), false, 1);
    EXPECT_GT(other.error, 0.01);
    EXPECT_EQ(other.heatmap.width, 0);
}

}  // namespace
}  // namespace boxlod
