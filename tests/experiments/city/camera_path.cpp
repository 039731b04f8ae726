#include "experiments/city/camera_path.h"

#include "base/input_error.h"
#include "data_gen/city.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boxlod;

namespace {

std::string error_of(const std::string& text) {
    try {
        parse_keyframes(text, "path.txt");
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST(CameraPath, ParsesKeyframesWithComments) {
    auto keys = parse_keyframes("# a dolly\n0 0 2 50  0 2 0\n\n1.5 1 2 30 0 2 0  # closer\n4 0 5 10 0 0 0\n",
                                "path.txt");
    ASSERT_EQ(keys.size(), 3u);
    EXPECT_EQ(keys[1].time, 1.5);
    EXPECT_EQ(keys[1].pose.eye, Eigen::Vector3f(1, 2, 30));
    EXPECT_EQ(keys[2].pose.target, Eigen::Vector3f(0, 0, 0));
}

TEST(CameraPath, BadKeyframesNameFileAndLine) {
    EXPECT_EQ(error_of("0 0 0 1 0 0 0\n"), "");
    EXPECT_EQ(error_of("0 0 0 1 0 0 0\n# fine\n1 0 0 1 0 0\n"),
              "path.txt: line 3: expected 'time x y z tx ty tz' (7 numbers), got 6");
    EXPECT_EQ(error_of("0 0 0 1 0 0 0\n1 0 0 1 0 0 x\n"), "path.txt: line 2: expected a number, got 'x'");
    EXPECT_EQ(
        error_of("0 0 0 1 0 0 0\n0 0 0 2 0 0 0\n").rfind("path.txt: line 2: times must increase strictly", 0),
        0u);
    EXPECT_EQ(error_of("0 1 1 1 1 1 1\n"), "path.txt: line 1: the eye and the target coincide");
    EXPECT_EQ(error_of("0 nan 0 1 0 0 0\n"), "path.txt: line 1: expected a number, got 'nan'");
    EXPECT_EQ(error_of("# nothing\n\n"), "path.txt: no keyframes (lines 'time x y z tx ty tz')");
    try {
        load_keyframes("/nonexistent/path.txt");
        FAIL() << "no error for a missing file";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()), "/nonexistent/path.txt: no such file");
    }
}

TEST(CameraPath, InterpolationPassesThroughEveryKeyAndIsSmooth) {
    auto keys = parse_keyframes("0 0 2 50 0 2 0\n1 10 2 30 0 0 0\n3 0 8 10 5 0 0\n4 -5 2 0 0 1 0\n", "k");
    for (const Keyframe& key : keys) {
        CameraPose pose = pose_at(keys, key.time);
        EXPECT_EQ(pose.eye, key.pose.eye);
        EXPECT_EQ(pose.target, key.pose.target);
    }
    // Continuous at a key: just before and just after are both close to it.
    CameraPose before = pose_at(keys, 1 - 1e-6), after = pose_at(keys, 1 + 1e-6);
    EXPECT_LT((before.eye - keys[1].pose.eye).norm(), 1e-3f);
    EXPECT_LT((after.eye - keys[1].pose.eye).norm(), 1e-3f);
    // Catmull-Rom, not linear: at t = 2 the eye leaves the chord from key 1 to key 2.
    Eigen::Vector3f chord_middle = (keys[1].pose.eye + keys[2].pose.eye) / 2;
    EXPECT_GT((pose_at(keys, 2).eye - chord_middle).norm(), 0.1f);
    // Clamped outside the keys.
    EXPECT_EQ(pose_at(keys, -5).eye, keys[0].pose.eye);
    EXPECT_EQ(pose_at(keys, 9).eye, keys[3].pose.eye);
    // Collinear keys evenly spaced in time give evenly spaced points on the line.
    auto line = parse_keyframes("0 0 0 0 0 0 -1\n1 0 0 10 0 0 -1\n2 0 0 20 0 0 -1\n", "line");
    auto poses = sample_keyframes(line, 5);
    ASSERT_EQ(poses.size(), 5u);
    for (int k = 0; k < 5; ++k) {
        EXPECT_NEAR(poses[std::size_t(k)].eye.z(), 5.0f * float(k), 1e-5f);
        EXPECT_EQ(poses[std::size_t(k)].eye.x(), 0);
    }
    EXPECT_EQ(sample_keyframes(line, 1).front().eye, line.front().pose.eye);
}

TEST(CameraPath, OrbitKeepsItsRadiusAndLooksAtTheCentre) {
    Eigen::Vector3f center(3, 1, -2);
    auto poses = orbit_path(center, 50, 20, 24);
    ASSERT_EQ(poses.size(), 24u);
    for (const CameraPose& pose : poses) {
        Eigen::Vector3f offset = pose.eye - center;
        EXPECT_NEAR(Eigen::Vector2f(offset.x(), offset.z()).norm(), 50, 1e-4);
        EXPECT_NEAR(offset.y(), 20, 1e-5);
        EXPECT_EQ(pose.target, center);
    }
    EXPECT_GT((poses[0].eye - poses[12].eye).norm(), 99.9f);  // half a turn: opposite sides
}

TEST(CameraPath, CityPathsOrbitTheCityAndWalkDownAStreet) {
    CityOptions options;
    options.buildings = 4;
    CityPlan city = plan_city(options);
    Bounds bounds = model_bounds(generate_city(options));
    auto orbit = city_path("orbit", city, bounds, 45, 8);
    ASSERT_EQ(orbit.size(), 8u);
    float radius = (orbit[0].eye - bounds.center()).norm();
    EXPECT_GT(radius, bounds.size().norm() / 2);  // outside the city
    for (const CameraPose& pose : orbit) {
        EXPECT_NEAR((pose.eye - bounds.center()).norm(), radius, 1e-3f * radius);
        EXPECT_EQ(pose.target, bounds.center());
    }
    // The street: 2 m above the ground, along x from one edge of the city to the other,
    // between the two rows of lots (z = 0 in a 2 x 2 city), looking ahead.
    auto street = city_path("street", city, bounds, 45, 5);
    ASSERT_EQ(street.size(), 5u);
    for (const CameraPose& pose : street) {
        EXPECT_NEAR(pose.eye.y(), 2, 1e-4);
        EXPECT_NEAR(pose.eye.z(), 0, 1e-3);
        Eigen::Vector3f ahead = (pose.target - pose.eye).normalized();
        EXPECT_NEAR(ahead.x(), 1, 1e-6);
    }
    EXPECT_NEAR(street.front().eye.x(), bounds.min.x(), 1e-3);
    EXPECT_NEAR(street.back().eye.x(), bounds.max.x(), 1e-3);
    EXPECT_THROW(city_path("sideways", city, bounds, 45, 5), InputError);
}
