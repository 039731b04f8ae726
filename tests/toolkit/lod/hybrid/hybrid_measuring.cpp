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

namespace {

// An axis-aligned box's 12 triangles, appended to `mesh`.
void add_box(Mesh& mesh, const Eigen::Vector3f& low, const Eigen::Vector3f& high) {
    const auto first = std::uint32_t(mesh.positions.size());
    for (int k = 0; k < 8; ++k)
        mesh.positions.push_back(
            {k & 1 ? high.x() : low.x(), k & 2 ? high.y() : low.y(), k & 4 ? high.z() : low.z()});
    for (std::uint32_t i : {0, 1, 3, 0, 3, 2, 4, 7, 5, 4, 6, 7, 0, 4, 5, 0, 5, 1,
                            2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3})
        mesh.indices.push_back(first + i);
}

}  // namespace

// A building is seen from above its ground: what hangs under its floor, hidden
// from every raised corner, is no error, and the same on its roof is.
TEST(HybridMeasuring, WhatOnlyAViewFromBelowWouldSeeCostsNothing) {
    MeasuringView view;
    view.sphere.center = Eigen::Vector3f(0.5f, 0.5f, 0.5f);
    view.sphere.radius = 1.2f;
    view.side = 16;
    view.pixel = 2 * view.sphere.radius / float(view.side);
    Mesh building, under, on_top;
    add_box(building, Eigen::Vector3f::Zero(), Eigen::Vector3f::Ones());
    under = on_top = building;
    add_box(under, {0.4f, -0.25f, 0.4f}, {0.6f, -0.05f, 0.6f});
    add_box(on_top, {0.4f, 1.05f, 0.4f}, {0.6f, 1.25f, 0.6f});
    const auto seen = [&](const Mesh& mesh) {
        return compared_views(render_views({Batch{&mesh, {}}}, view, RenderMode::untextured));
    };
    EXPECT_EQ(pixel_error_sum(seen(building), seen(under)), 0);
    EXPECT_GT(pixel_error_sum(seen(building), seen(on_top)), 0);
}
