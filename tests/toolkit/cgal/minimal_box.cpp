#include "toolkit/cgal/minimal_box.h"

#include "toolkit/cgal/box_fit.h"
#include "toolkit/lod/pages/boxes.h"

#include "box_checks.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include "base/random.h"

#include <algorithm>

namespace boxlod {
namespace {

using test::bitwise_equal;
using test::encloses;
using test::valid_frame;

OrientedBox rotated_box() {
    OrientedBox box;
    box.center = {1, 2, 3};
    box.axes = Eigen::AngleAxisf(0.6f, Eigen::Vector3f(1, 2, 3).normalized()).toRotationMatrix();
    box.half_extents = {2, 1, 0.5f};
    return box;
}

std::vector<Eigen::Vector3f> corners_of(const OrientedBox& box) {
    auto corners = box_corners(box);
    return {corners.begin(), corners.end()};
}

TEST(MinimalBox, CornersOfARotatedBoxGiveThatBox) {
    OrientedBox expected = rotated_box();
    OrientedBox box = minimal_box(corners_of(expected), 7);
    EXPECT_NEAR(box_volume(box), box_volume(expected), 1e-4 * box_volume(expected));
    EXPECT_TRUE(box.center.isApprox(expected.center, 1e-4f));
    // The same axes up to order and sign: |A^T E| is a permutation matrix.
    Eigen::Matrix3f match = (box.axes.transpose() * expected.axes).cwiseAbs();
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(match.row(r).maxCoeff(), 1, 1e-4);
    std::vector<float> sides(box.half_extents.data(), box.half_extents.data() + 3);
    std::sort(sides.begin(), sides.end());
    EXPECT_NEAR(sides[0], 0.5f, 1e-4);
    EXPECT_NEAR(sides[1], 1, 1e-4);
    EXPECT_NEAR(sides[2], 2, 1e-4);
    EXPECT_TRUE(valid_frame(box));
    for (const Eigen::Vector3f& p : corners_of(expected)) EXPECT_TRUE(encloses(box, p));
}

TEST(MinimalBox, EnclosesACloudAndBeatsTheAxisAlignedBox) {
    // A deterministic cloud along a tilted slab (the project's PCG32; no std distributions).
    std::vector<Eigen::Vector3f> points;
    Pcg32 random(12345, 1);
    auto next = [&] { return float(random.uniform()); };
    Eigen::Matrix3f r = Eigen::AngleAxisf(0.5f, Eigen::Vector3f(0, 1, 1).normalized()).toRotationMatrix();
    for (int i = 0; i < 300; ++i)
        points.push_back(r * Eigen::Vector3f(4 * next(), 2 * next(), 0.3f * next()));
    OrientedBox box = minimal_box(points, 1);
    for (const Eigen::Vector3f& p : points) EXPECT_TRUE(encloses(box, p));
    EXPECT_TRUE(valid_frame(box));
    OrientedBox aligned = fit_box(Eigen::Matrix3d::Identity(), points);
    EXPECT_LT(box_volume(box), 0.5f * box_volume(aligned));
}

TEST(MinimalBox, SamePointsAnyOrderGiveTheSameBits) {
    std::vector<Eigen::Vector3f> points = corners_of(rotated_box());
    points.push_back(rotated_box().center);  // an interior point
    OrientedBox a = minimal_box(points, 42);
    std::vector<Eigen::Vector3f> shuffled(points.rbegin(), points.rend());
    shuffled.push_back(points[3]);  // a duplicate
    OrientedBox b = minimal_box(shuffled, 42);
    EXPECT_TRUE(bitwise_equal(a, b));
    EXPECT_TRUE(bitwise_equal(a, minimal_box(hull_vertices(points), 42)));
}

TEST(MinimalBox, TranslatedCopiesShareTheirShapeAndOrientation) {
    // Dyadic coordinates, so the translation is exact in float.
    std::vector<Eigen::Vector3f> points{{0, 0, 0}, {2, 0.5f, 0}, {0.25f, 1, 0.5f}, {1, 1, 2}, {2, 2, 1.5f}};
    std::vector<Eigen::Vector3f> moved;
    for (const Eigen::Vector3f& p : points) moved.push_back(p + Eigen::Vector3f(8, -4, 16));
    HullShape shape = hull_shape(hull_vertices(points));
    EXPECT_EQ(shape, hull_shape(hull_vertices(moved)));
    EXPECT_FALSE(shape.flat);
    OrientedBox a = minimal_box(points, 3), b = minimal_box(moved, 3);
    EXPECT_EQ(a.axes, b.axes);
    // Each copy fits its own box around its own points (own rounding of the centre).
    EXPECT_TRUE(a.half_extents.isApprox(b.half_extents, 1e-6f));
    EXPECT_TRUE(b.center.isApprox(a.center + Eigen::Vector3f(8, -4, 16), 1e-6f));
}

TEST(MinimalBox, HullVerticesAreTheCornersOnly) {
    std::vector<Eigen::Vector3f> points;
    for (int x = 0; x <= 2; ++x)
        for (int y = 0; y <= 2; ++y)
            for (int z = 0; z <= 2; ++z)
                points.emplace_back(float(x), float(y), float(z));  // corners, edge midpoints, faces, centre
    points.emplace_back(-0.f, 0.f, 0.f);
    std::vector<Eigen::Vector3f> hull = hull_vertices(points);
    ASSERT_EQ(hull.size(), 8u);
    EXPECT_EQ(hull.front(), Eigen::Vector3f(0, 0, 0));
    EXPECT_FALSE(std::signbit(hull.front().x()));
    EXPECT_EQ(hull[1], Eigen::Vector3f(0, 0, 2));
    EXPECT_EQ(hull.back(), Eigen::Vector3f(2, 2, 2));
    EXPECT_TRUE(hull_vertices({}).empty());
}

TEST(MinimalBox, SinglePointHasAPositiveThickness) {
    std::vector<Eigen::Vector3f> points{{1, 2, 3}, {1, 2, 3}};
    OrientedBox box = minimal_box(points, 0);
    EXPECT_EQ(box.center, Eigen::Vector3f(1, 2, 3));
    EXPECT_TRUE(box.half_extents.allFinite());
    EXPECT_GT(box.half_extents.minCoeff(), 0);
    EXPECT_LE(box.half_extents.maxCoeff(), 1e-5f);
    EXPECT_TRUE(valid_frame(box));
}

TEST(MinimalBox, CollinearPointsGiveASegmentBox) {
    std::vector<Eigen::Vector3f> points{{0, 0, 0}, {1, 2, 2}, {2, 4, 4}, {3, 6, 6}};
    OrientedBox box = minimal_box(points, 0);
    EXPECT_TRUE(box.axes.col(0).cwiseAbs().isApprox(Eigen::Vector3f(1, 2, 2) / 3, 1e-6f));
    EXPECT_NEAR(box.half_extents[0], 4.5f, 1e-5);
    EXPECT_GT(box.half_extents[1], 0);
    EXPECT_GT(box.half_extents[2], 0);
    EXPECT_LT(box.half_extents[1], 1e-3f);
    EXPECT_TRUE(valid_frame(box));
    for (const Eigen::Vector3f& p : points) EXPECT_TRUE(encloses(box, p));
}

TEST(MinimalBox, CoplanarPointsGiveTheMinimumAreaRectangle) {
    // A 4 x 2 rectangle turned 30 degrees in a tilted plane, with points inside and on its edges.
    Eigen::Matrix3f frame =
        Eigen::AngleAxisf(0.8f, Eigen::Vector3f(1, -1, 0.5f).normalized()).toRotationMatrix();
    Eigen::Matrix2f turn = Eigen::Rotation2Df(0.5236f).toRotationMatrix();
    std::vector<Eigen::Vector3f> points;
    for (Eigen::Vector2f q : {Eigen::Vector2f(-2, -1), Eigen::Vector2f(2, -1), Eigen::Vector2f(2, 1),
                              Eigen::Vector2f(-2, 1), Eigen::Vector2f(0, 1), Eigen::Vector2f(0.5f, 0.2f)}) {
        Eigen::Vector2f t = turn * q;
        points.push_back(frame * Eigen::Vector3f(t.x(), t.y(), 0) + Eigen::Vector3f(10, 0, 0));
    }
    OrientedBox box = minimal_box(points, 0);
    std::vector<float> sides(box.half_extents.data(), box.half_extents.data() + 3);
    std::sort(sides.begin(), sides.end());
    EXPECT_GT(sides[0], 0);
    EXPECT_LT(sides[0], 1e-3f);
    EXPECT_NEAR(sides[1], 1, 1e-5);
    EXPECT_NEAR(sides[2], 2, 1e-5);
    EXPECT_TRUE(valid_frame(box));
    for (const Eigen::Vector3f& p : points) EXPECT_TRUE(encloses(box, p));
}

TEST(MinimalBox, EmptyInputGivesATinyValidBox) {
    OrientedBox box = minimal_box({}, 0);
    EXPECT_TRUE(box.center.allFinite());
    EXPECT_GT(box.half_extents.minCoeff(), 0);
    EXPECT_TRUE(valid_frame(box));
}

}  // namespace
}  // namespace boxlod
