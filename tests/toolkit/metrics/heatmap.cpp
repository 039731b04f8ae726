#include "toolkit/metrics/heatmap.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boxlod;

using Rgb = std::array<std::uint8_t, 3>;

TEST(Heatmap, RampKnotsAreBlackRedYellowWhite) {
    EXPECT_EQ(heat_color(0.0), (Rgb{0, 0, 0}));
    EXPECT_EQ(heat_color(1.0 / 3), (Rgb{255, 0, 0}));
    EXPECT_EQ(heat_color(2.0 / 3), (Rgb{255, 255, 0}));
    EXPECT_EQ(heat_color(1.0), (Rgb{255, 255, 255}));
    EXPECT_EQ(heat_color(0.5), (Rgb{255, 128, 0}));
}

TEST(Heatmap, OutOfRangeValuesAreClamped) {
    EXPECT_EQ(heat_color(-2.0), heat_color(0.0));
    EXPECT_EQ(heat_color(7.0), heat_color(1.0));
    EXPECT_EQ(heat_color(std::nan("")), heat_color(1.0));
}

TEST(Heatmap, LargerErrorsAreNeverDarker) {
    int previous = -1;
    for (int i = 0; i <= 300; ++i) {
        Rgb c = heat_color(i / 300.0);
        int brightness = c[0] + c[1] + c[2];
        EXPECT_GE(brightness, previous) << i;
        previous = brightness;
    }
}

TEST(Heatmap, ImageHasThePlanesSizeAndColours) {
    Plane error(3, 2, 1);
    *error.at(2, 1) = 1;
    Image8 image = error_heatmap(error);
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 2);
    ASSERT_EQ(image.channels, 3);
    EXPECT_EQ(image.at(2, 1)[1], 255);
    EXPECT_EQ(image.at(0, 0)[0], 0);
}
