#include "toolkit/lod/pages/texture_sizing.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boxlod;

namespace {
TextureSizing sizing(float fovy, float distance, float resolution, int max_size = 4096) {
    TextureSizing s;
    s.fovy_degrees = fovy;
    s.distance = distance;
    s.resolution = resolution;
    s.max_texture_size = max_size;
    s.gutter = 2;
    return s;
}
}  // namespace

TEST(TextureSizing, OnePixelSpansTheExpectedWorldSize) {
    // fovy 90 at distance 10 sees 20 units over 1000 pixels: 2 cm per pixel.
    EXPECT_NEAR(pixel_world_size(sizing(90, 10, 1000)), 0.02f, 1e-7f);
    EXPECT_NEAR(pixel_world_size(sizing(60, 5, 1080)), 2 * 5 * std::tan(M_PI / 6) / 1080, 1e-7);
}

TEST(TextureSizing, FacesGetCeilTexelsAtLeastOne) {
    TextureSizing s = sizing(90, 10, 1000);  // p = 0.02
    EXPECT_EQ(face_texels(1.0f, 0.5f, s), Eigen::Vector2i(50, 25));
    EXPECT_EQ(face_texels(1.01f, 0.001f, s), Eigen::Vector2i(51, 1));
    EXPECT_EQ(face_texels(0, 0, s), Eigen::Vector2i(1, 1));
}

TEST(TextureSizing, LargeFacesScaleDownUniformlyToFitTheLargestPage) {
    TextureSizing s = sizing(90, 10, 1000, 256);      // limit 256 - 4 = 252 texels
    Eigen::Vector2i t = face_texels(10.0f, 5.0f, s);  // 500 x 250 wanted
    EXPECT_EQ(t, Eigen::Vector2i(252, 126));
}

TEST(TextureSizing, MinDistanceIsWhereTheLargestFaceJustFits) {
    TextureSizing s = sizing(45, 1, 1080, 1024);
    float longest = 30;
    float d = min_distance(longest, s);
    s.distance = d * 1.0001f;
    EXPECT_LE(face_texels(longest, 1, s).x(), 1020);
    EXPECT_GE(face_texels(longest, 1, s).x(), 1019);
    s.distance = d * 0.98f;  // closer needs more texels than a page holds: scaled
    float p = pixel_world_size(s);
    EXPECT_GT(std::ceil(longest / p), 1020);
}
