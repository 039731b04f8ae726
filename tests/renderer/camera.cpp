#include "renderer/camera.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <set>

using namespace boxlod;

TEST(Camera, TwentySixNamedPositionsParseBack) {
    auto names = camera_position_names();
    ASSERT_EQ(names.size(), 26u);
    std::set<std::string> unique(names.begin(), names.end());
    EXPECT_EQ(unique.size(), 26u);
    for (const auto& name : names) {
        auto d = camera_direction(name);
        ASSERT_TRUE(d) << name;
        EXPECT_FALSE(d->isZero());
    }
    EXPECT_EQ(*camera_direction("+X+Y+Z"), Eigen::Vector3f(1, 1, 1));
    EXPECT_EQ(*camera_direction("-y"), Eigen::Vector3f(0, -1, 0));
    for (const char* bad : {"", "X", "+X+X", "+W", "+X-", "++X"}) EXPECT_FALSE(camera_direction(bad)) << bad;
}

TEST(Camera, PositionLooksAtTheCentreWithTheManualsUpVectors) {
    Eigen::Vector3f centre(1, 2, 3);
    Camera c = camera_at_position({1, 1, 1}, centre, 10, 45, 2);
    EXPECT_NEAR((c.position - centre).norm(), 10, 1e-5);
    EXPECT_EQ(c.up, Eigen::Vector3f(0, 1, 0));
    EXPECT_EQ(camera_at_position({0, 1, 0}, centre, 10, 45, 2).up, Eigen::Vector3f(0, 0, -1));
    EXPECT_EQ(camera_at_position({0, -1, 0}, centre, 10, 45, 2).up, Eigen::Vector3f(0, 0, 1));
    EXPECT_FLOAT_EQ(c.near_plane, 8);
    EXPECT_FLOAT_EQ(c.far_plane, 12);
}

// One depth range for every framing camera: the sphere just fits outside it,
// a positive near plane inside it (the viewer at the model's centre, a
// street in a city), and far stays beyond near however far the camera is.
TEST(Camera, DepthRangeFitsTheSphereFromOutsideAndInside) {
    Camera c;
    fit_depth_range(c, 10, 2);
    EXPECT_EQ(c.near_plane, 8);
    EXPECT_EQ(c.far_plane, 12);
    fit_depth_range(c, 0, 5);  // at the centre
    EXPECT_GT(c.near_plane, 0);
    EXPECT_EQ(c.far_plane, 5);
    fit_depth_range(c, 3, 5);  // inside: near at a thousandth of the distance
    EXPECT_FLOAT_EQ(c.near_plane, 3e-3f);
    EXPECT_EQ(c.far_plane, 8);
    fit_depth_range(c, 1e7f, 1);  // far away: far and near not equal in floats
    EXPECT_GT(c.far_plane, c.near_plane * 1.001f);
}

TEST(Camera, ProjectionMapsNearAndFarToTheDepthRange) {
    Camera c;
    c.position = {0, 0, 0}, c.target = {0, 0, -1}, c.near_plane = 2, c.far_plane = 20;
    Eigen::Matrix4f m = projection_matrix(c, 1.5f) * view_matrix(c);
    Eigen::Vector4f near = m * Eigen::Vector4f(0, 0, -2, 1), far = m * Eigen::Vector4f(0, 0, -20, 1);
    EXPECT_NEAR(near.z() / near.w(), -1, 1e-6);
    EXPECT_NEAR(far.z() / far.w(), 1, 1e-6);
    // The top of the view frustum at distance 2 maps to y = 1.
    float top = 2 * std::tan(22.5f * float(M_PI) / 180);
    Eigen::Vector4f edge = m * Eigen::Vector4f(0, top, -2, 1);
    EXPECT_NEAR(edge.y() / edge.w(), 1, 1e-6);
    c.orthographic = true;
    c.left = -3, c.right = 1, c.bottom = -1, c.top = 2;
    Eigen::Vector4f corner = projection_matrix(c, 1) * view_matrix(c) * Eigen::Vector4f(1, 2, -20, 1);
    EXPECT_NEAR(corner.x(), 1, 1e-6);
    EXPECT_NEAR(corner.y(), 1, 1e-6);
    EXPECT_NEAR(corner.z(), 1, 1e-6);
}
