#include "toolkit/model/framing.h"

#include "lod_scene.h"

#include <gtest/gtest.h>

using namespace boxlod;

TEST(Framing, CentreAndRadiusAreTheBoundingBoxsCentreAndHalfDiagonal) {
    Bounds bounds;
    bounds.add({0, 0, 0});
    bounds.add({2, 4, 4});
    Framing framing = framing_of(bounds);
    EXPECT_EQ(framing.center, Eigen::Vector3f(1, 2, 2));
    EXPECT_FLOAT_EQ(framing.radius, 3);
    Model model = test::lod_test_building();
    EXPECT_EQ(model_framing(model).center, model_bounds(model).center());
}

TEST(Framing, TheDefaultDistanceFitsTheSphereIntoTheFieldOfView) {
    Bounds bounds;
    bounds.add({-1, -1, -1});
    bounds.add({1, 1, 1});
    Framing framing = framing_of(bounds);
    float distance = framing_distance(framing, 45);
    // The sphere's angular radius stays inside half the field of view.
    EXPECT_LT(std::asin(framing.radius / distance), 22.5f * float(M_PI) / 180);
    EXPECT_GT(std::asin(framing.radius / distance), 0.8f * 22.5f * float(M_PI) / 180);
}

TEST(Framing, TheCameraLooksAtTheCentreFromTheNamedDirectionAndKeepsTheSphereBetweenNearAndFar) {
    Bounds bounds;
    bounds.add({9, 0, 0});
    bounds.add({11, 2, 2});
    Framing framing = framing_of(bounds);
    Camera camera = framed_camera(framing, *camera_direction("+X"), 10, 45);
    EXPECT_EQ(camera.target, framing.center);
    EXPECT_TRUE(camera.position.isApprox(framing.center + Eigen::Vector3f(10, 0, 0)));
    EXPECT_LE(camera.near_plane, 10 - framing.radius);
    EXPECT_GE(camera.far_plane, 10 + framing.radius);
    // A degenerate model still gets a positive radius.
    Bounds point;
    point.add({1, 1, 1});
    EXPECT_GT(framing_of(point).radius, 0);
}
