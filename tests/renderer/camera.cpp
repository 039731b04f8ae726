#include "renderer/camera.h"

#include "renderer/renderer.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
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
    c.position = {0, 0, 0};
    c.target = {0, 0, -1};
    c.near_plane = 2;
    c.far_plane = 20;
    Eigen::Matrix4f m = projection_matrix(c, 1.5f) * view_matrix(c);
    Eigen::Vector4f near = m * Eigen::Vector4f(0, 0, -2, 1), far = m * Eigen::Vector4f(0, 0, -20, 1);
    EXPECT_NEAR(near.z() / near.w(), -1, 1e-6);
    EXPECT_NEAR(far.z() / far.w(), 1, 1e-6);
    // The top of the view frustum at distance 2 maps to y = 1.
    float top = 2 * std::tan(22.5f * float(M_PI) / 180);
    Eigen::Vector4f edge = m * Eigen::Vector4f(0, top, -2, 1);
    EXPECT_NEAR(edge.y() / edge.w(), 1, 1e-6);
    c.orthographic = true;
    c.left = -3;
    c.right = 1;
    c.bottom = -1;
    c.top = 2;
    Eigen::Vector4f corner = projection_matrix(c, 1) * view_matrix(c) * Eigen::Vector4f(1, 2, -20, 1);
    EXPECT_NEAR(corner.x(), 1, 1e-6);
    EXPECT_NEAR(corner.y(), 1, 1e-6);
    EXPECT_NEAR(corner.z(), 1, 1e-6);
}

// A sphere judged outside the view holds nothing the renderer draws: a cube
// inscribed in it leaves the frame empty. Spheres around the view volume's
// edges, some in, some out, from a perspective and an orthographic camera.
TEST(Camera, ASphereOutsideTheViewDrawsNothing) {
    Camera camera;
    camera.position = {0, 0, 0};
    camera.target = {0, 0, -1};
    camera.fovy_degrees = 60;
    camera.near_plane = 0.5f;
    camera.far_plane = 50;
    EXPECT_TRUE(sphere_in_view(camera, 1.5f, {0, 0, -10}, 1));
    EXPECT_FALSE(sphere_in_view(camera, 1.5f, {0, 0, 10}, 1));     // behind
    EXPECT_FALSE(sphere_in_view(camera, 1.5f, {0, 0, -60}, 1));    // beyond far
    EXPECT_FALSE(sphere_in_view(camera, 1.5f, {100, 0, -10}, 1));  // aside
    Camera orthographic = camera;
    orthographic.orthographic = true;
    orthographic.left = -4;
    orthographic.right = 4;
    orthographic.bottom = -3;
    orthographic.top = 3;
    int outside = 0, inside = 0;
    for (const Camera& c : {camera, orthographic})
        for (int i = 0; i < 200; ++i) {
            // Centres on a spiral sweeping across the edges of the view.
            const float angle = float(i) * 0.7f, reach = 2 + float(i % 40) * 0.35f,
                        depth = -1 - float(i % 17) * 3.5f;
            const Eigen::Vector3f center(reach * std::cos(angle) * -depth * 0.3f,
                                         reach * std::sin(angle) * -depth * 0.2f, depth);
            const float radius = 0.3f + float(i % 5) * 0.4f, half = radius / std::sqrt(3.0f);
            Mesh cube;
            for (int k = 0; k < 8; ++k)
                cube.positions.push_back(
                    center + half * Eigen::Vector3f(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
            cube.indices = {0, 1, 3, 0, 3, 2, 4, 7, 5, 4, 6, 7, 0, 4, 5, 0, 5, 1,
                            2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
            RenderSettings settings;
            settings.camera = c;
            settings.mode = RenderMode::untextured;
            Frame frame = make_frame(48, 32, {1, 1, 1});
            render({Batch{&cube, {}}}, settings, frame);
            bool drawn = false;
            for (const Eigen::Vector4f& color : frame.color) drawn = drawn || color.w() > 0;
            if (sphere_in_view(c, 1.5f, center, radius)) {
                ++inside;
            } else {
                ++outside;
                EXPECT_FALSE(drawn) << i;
            }
        }
    EXPECT_GT(outside, 40);
    EXPECT_GT(inside, 40);
}
