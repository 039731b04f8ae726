#include "toolkit/metrics/image_metrics.h"

#include "metric_images.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace boxlod;
using namespace boxlod::test;

namespace {
Image8 offset(const Image8& image, int delta, int only_channel = -1) {
    Image8 out = image;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (only_channel < 0 || c == only_channel)
                    out.at(x, y)[c] = std::uint8_t(out.at(x, y)[c] + delta);
    return out;
}
Image8 negative(const Image8& image) {
    Image8 out = image;
    for (auto& v : out.pixels) v = std::uint8_t(255 - v);
    return out;
}
}  // namespace

TEST(ImageMetrics, IdenticalImagesAreAPerfectMatch) {
    Image8 a = pattern_image(64, 48);
    EXPECT_EQ(rmse(a, a), 0.0);
    EXPECT_EQ(psnr(a, a), std::numeric_limits<double>::infinity());
    EXPECT_NEAR(ssim(a, a, 2), 1.0, 1e-15);
}

TEST(ImageMetrics, ConstantOffsetGivesExactRmseAndPsnr) {
    Image8 a = pattern_image(40, 30), b = offset(a, 10);
    EXPECT_DOUBLE_EQ(rmse(a, b), 10.0 / 255.0);
    EXPECT_DOUBLE_EQ(psnr(a, b), 20 * std::log10(25.5));
    // One channel of three: the mean square is a third.
    EXPECT_DOUBLE_EQ(rmse(a, offset(a, 10, 1)), std::sqrt(100.0 / 3.0) / 255.0);
    EXPECT_DOUBLE_EQ(rmse(b, a), rmse(a, b));
}

TEST(ImageMetrics, AlphaIsIgnored) {
    Image8 a(12, 12, 4, 200), b = a;
    for (int y = 0; y < 12; ++y) b.at(3, y)[3] = 0;
    EXPECT_EQ(rmse(a, b), 0.0);
}

TEST(ImageMetrics, RgbErrorMapIsThePerPixelRmsOverRgb) {
    Image8 a = flat_image(5, 4, 10, 20, 30), b = flat_image(5, 4, 13, 24, 30);
    Plane map = rgb_error_map(a, b);
    ASSERT_EQ(map.width, 5);
    ASSERT_EQ(map.height, 4);
    for (double v : map.pixels) EXPECT_DOUBLE_EQ(v, std::sqrt(25.0 / 3.0) / 255.0);
}

TEST(ImageMetrics, LumaUsesBt601WeightsOnEncodedValues) {
    Plane luma = luma_plane(flat_image(2, 2, 255, 0, 0));
    EXPECT_DOUBLE_EQ(*luma.at(1, 1), 0.299);
    EXPECT_NEAR(*luma_plane(flat_image(2, 2, 51, 102, 204)).at(0, 0),
                (0.299 * 51 + 0.587 * 102 + 0.114 * 204) / 255, 1e-15);
}

TEST(ImageMetrics, SsimOfFlatImagesIsTheLuminanceTerm) {
    // No variance: SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1) with C1 = (0.01 * 1)^2 (Wang et al. 2004, eq.
    // 13).
    double mx = 100 / 255.0, my = 150 / 255.0, c1 = 1e-4;
    double expected = (2 * mx * my + c1) / (mx * mx + my * my + c1);
    EXPECT_NEAR(ssim(flat_image(20, 16, 100, 100, 100), flat_image(20, 16, 150, 150, 150), 1), expected,
                1e-12);
}

TEST(ImageMetrics, SsimOfANegativeIsLow) {
    Image8 a = pattern_image(64, 64);
    double s = ssim(a, negative(a), 2);
    EXPECT_LT(s, -0.5);
    EXPECT_GE(s, -1.0);
}

TEST(ImageMetrics, SsimFallsAsBlurGrowsAndIsSymmetric) {
    Image8 a = pattern_image(80, 60);
    double previous = 1.0;
    for (int radius : {1, 2, 4}) {
        Image8 b = box_blur(a, radius);
        double s = ssim(a, b, 2);
        EXPECT_LT(s, previous) << radius;
        EXPECT_DOUBLE_EQ(ssim(b, a, 2), s);
        previous = s;
    }
}

TEST(ImageMetrics, SsimIsTheSameForAnyThreadCount) {
    Image8 a = pattern_image(131, 77), b = box_blur(a, 1);
    double one = ssim(a, b, 1);
    for (int threads : {2, 5}) EXPECT_EQ(ssim(a, b, threads), one);
}

TEST(ImageMetrics, BadInputIsRejected) {
    EXPECT_THROW(rmse(pattern_image(10, 10), pattern_image(10, 11)), std::invalid_argument);
    EXPECT_THROW(ssim(pattern_image(20, 20), pattern_image(21, 20), 1), std::invalid_argument);
    EXPECT_THROW(ssim(pattern_image(10, 30), pattern_image(10, 30), 1),
                 std::invalid_argument);  // smaller than the window
    EXPECT_NO_THROW(ssim(pattern_image(11, 11), pattern_image(11, 11), 1));
}
