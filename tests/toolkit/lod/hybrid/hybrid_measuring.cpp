#include "toolkit/lod/hybrid/hybrid_measuring.h"

#include <gtest/gtest.h>

using namespace boxlod;

TEST(HybridMeasuring, PixelErrorCountsCoverageAndColour) {
    const Eigen::Vector4f red(1, 0, 0, 1), black(0, 0, 0, 1), none(0, 0, 0, 0);
    EXPECT_EQ(hybrid_pixel_error(red, red), 0);
    EXPECT_EQ(hybrid_pixel_error(red, none), 1);                  // covered against background
    EXPECT_NEAR(hybrid_pixel_error(red, black), 1.0 / 3, 1e-12);  // one channel of three, fully apart
    EXPECT_EQ(hybrid_pixel_error(none, none), 0);
}

TEST(HybridMeasuring, SumsThePixelErrorsOfEveryDirection) {
    Frame covered = make_frame(2, 2, {0, 0, 0}), empty = make_frame(2, 2, {0, 0, 0});
    for (Eigen::Vector4f& c : covered.color) c = Eigen::Vector4f(1, 0, 0, 1);
    empty.color.assign(empty.color.size(), Eigen::Vector4f::Zero());
    const auto original = compared_views({covered, covered}), proxy = compared_views({covered, empty});
    EXPECT_EQ(pixel_error_sum(original, original), 0);
    EXPECT_EQ(pixel_error_sum(original, proxy), 4);  // four pixels of one direction uncovered
}

TEST(HybridMeasuring, RendersASphereFromEachDirectionAtItsSide) {
    MeasuringView view;
    view.sphere.center = Eigen::Vector3f::Zero();
    view.sphere.radius = 1;
    view.side = 8;
    view.pixel = 0.25f;
    const std::vector<Frame> frames = render_views({}, view, RenderMode::normal);
    ASSERT_EQ(int(frames.size()), measuring_directions);
    for (const Frame& frame : frames) {
        EXPECT_EQ(frame.width, 8);
        EXPECT_EQ(frame.height, 8);
    }
    EXPECT_EQ(render_views({}, view, RenderMode::normal, nullptr, false)[0].width, 16);  // supersampled
}
