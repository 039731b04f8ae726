#include "toolkit/metrics/flip.h"

#include "metric_images.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace boxlod;
using namespace boxlod::test;

namespace {

// FLIP's colour error of two flat images, from the paper's definitions and
// independently published CIELAB values (D65) of the sRGB primaries:
// green (87.737, -86.185, 83.181), blue (32.303, 79.197, -107.864).
double expected_flat_color_error(double hyab_distance) {
    auto hunt = [](double l, double a, double b) {
        return std::array<double, 3>{l, 0.01 * l * a, 0.01 * l * b};
    };
    auto green = hunt(87.737, -86.185, 83.181), blue = hunt(32.303, 79.197, -107.864);
    double cmax =
        std::pow(std::abs(green[0] - blue[0]) + std::hypot(green[1] - blue[1], green[2] - blue[2]), 0.7);
    double e = std::pow(hyab_distance, 0.7), pccmax = 0.4 * cmax;
    return e < pccmax ? 0.95 / pccmax * e : 0.95 + (e - pccmax) / (cmax - pccmax) * 0.05;
}

double max_of(const Plane& p) { return *std::max_element(p.pixels.begin(), p.pixels.end()); }
double min_of(const Plane& p) { return *std::min_element(p.pixels.begin(), p.pixels.end()); }

}  // namespace

TEST(Flip, IdenticalImagesHaveNoError) {
    Image8 a = pattern_image(70, 50);
    FlipResult r = flip(a, a, 67, 2);
    EXPECT_EQ(r.mean, 0.0);
    EXPECT_EQ(max_of(r.error), 0.0);
    ASSERT_EQ(r.error.width, 70);
    ASSERT_EQ(r.error.height, 50);
}

TEST(Flip, BlackAgainstWhiteIsTheLightnessDistanceOfOneHundred) {
    // L* 0 against L* 100, no chroma, no features: deltaE = deltaEc(HyAB = 100), about 0.967.
    Image8 black = flat_image(32, 24, 0, 0, 0), white = flat_image(32, 24, 255, 255, 255);
    double expected = expected_flat_color_error(100);
    EXPECT_NEAR(expected, 0.9674, 5e-4);
    FlipResult r = flip(black, white, 67, 1);
    EXPECT_NEAR(r.mean, expected, 2e-4);
    EXPECT_NEAR(min_of(r.error), max_of(r.error), 1e-9);  // flat
    EXPECT_EQ(flip(white, black, 67, 1).mean, r.mean);    // symmetric
}

TEST(Flip, GreenAgainstBlueIsTheMaximumError) {
    // The paper normalizes by the distance of green to blue: that pair maps to exactly 1.
    FlipResult r = flip(flat_image(16, 16, 0, 255, 0), flat_image(16, 16, 0, 0, 255), 67, 1);
    EXPECT_NEAR(r.mean, 1.0, 1e-9);
}

TEST(Flip, SmallGreyStepsLandInTheLinearPart) {
    // Grey 118 against grey 128: L* 49.7 against 53.6, below pc * cmax.
    Image8 a = flat_image(16, 16, 118, 118, 118), b = flat_image(16, 16, 128, 128, 128);
    auto lightness = [](double v) {
        double lin = v / 255 <= 0.04045 ? v / 255 / 12.92 : std::pow((v / 255 + 0.055) / 1.055, 2.4);
        return 116 * std::cbrt(lin) - 16;
    };
    double expected = expected_flat_color_error(lightness(128) - lightness(118));
    EXPECT_LT(expected, 0.95);
    EXPECT_NEAR(flip(a, b, 67, 1).mean, expected, 2e-4);
}

TEST(Flip, ErrorGrowsWithBlur) {
    Image8 a = pattern_image(96, 72);
    double previous = 0;
    for (int radius : {1, 2, 3, 5}) {
        double e = flip(a, box_blur(a, radius), 67, 2).mean;
        EXPECT_GT(e, previous) << radius;
        previous = e;
    }
    EXPECT_LT(previous, 1.0);
}

TEST(Flip, ErrorIsSymmetricAndBounded) {
    Image8 a = pattern_image(60, 40), b = box_blur(a, 2);
    FlipResult ab = flip(a, b, 67, 2), ba = flip(b, a, 67, 2);
    EXPECT_EQ(ab.error.pixels, ba.error.pixels);
    EXPECT_GE(min_of(ab.error), 0.0);
    EXPECT_LE(max_of(ab.error), 1.0);
}

TEST(Flip, ErrorStaysNearTheChange) {
    // A vertical edge moved by one pixel: large error on the edge, none far from it.
    Image8 a = flat_image(40, 20, 64, 64, 64), b = a;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 40; ++x) {
            if (x >= 20) std::fill_n(a.at(x, y), 3, 192);
            if (x >= 21) std::fill_n(b.at(x, y), 3, 192);
        }
    FlipResult r = flip(a, b, 67, 1);
    EXPECT_GT(*r.error.at(20, 10), 0.2);
    EXPECT_EQ(*r.error.at(2, 10), 0.0);
    EXPECT_EQ(*r.error.at(38, 10), 0.0);
}

TEST(Flip, FineDetailMattersLessWhenPixelsAreSmaller) {
    // A one-pixel checker against its mean grey: at more pixels per degree the eye blurs it away.
    Image8 checker = flat_image(48, 48, 0, 0, 0);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x)
            if ((x + y) % 2) std::fill_n(checker.at(x, y), 3, 255);
    Image8 grey = flat_image(48, 48, 188, 188, 188);  // sRGB of linear 0.5
    EXPECT_LT(flip(checker, grey, 200, 2).mean, flip(checker, grey, 20, 2).mean);
}

TEST(Flip, SameBitsForAnyThreadCount) {
    Image8 a = pattern_image(83, 59), b = box_blur(a, 1);
    FlipResult one = flip(a, b, 67, 1);
    for (int threads : {2, 3}) {
        FlipResult many = flip(a, b, 67, threads);
        EXPECT_EQ(many.error.pixels, one.error.pixels);
        EXPECT_EQ(many.mean, one.mean);
    }
}

// A sweep prepares each original once and compares every LoD with it; the thread_local
// row buffers must carry nothing over from one image (or one size) to the next.
TEST(Flip, APreparedReferenceServesManyTestImages) {
    Image8 a = pattern_image(83, 59);
    FlipReference prepared = prepare_flip_reference(a, 40, 2);
    for (int radius : {1, 2, 4}) {
        Image8 b = box_blur(a, radius);
        flip(pattern_image(30, 20), box_blur(pattern_image(30, 20), 1), 67, 2);  // other sizes in between
        FlipResult direct = flip(a, b, 40, 1), reused = flip(prepared, b, 2);
        EXPECT_GT(direct.mean, 0);
        EXPECT_EQ(reused.error.pixels, direct.error.pixels);
        EXPECT_EQ(reused.mean, direct.mean);
    }
}

// Where both images are equal within the filters' reach FLIP skips the
// work and writes 0; one differing pixel must still reach every pixel its
// widest filter (the blue-yellow CSF, radius 10 at 67 ppd) reaches, and no other.
TEST(Flip, OneDifferingPixelReachesTheWidestFilterAndNoFarther) {
    Image8 a = flat_image(64, 48, 128, 128, 128), b = a;
    b.at(30, 20)[2] = 255;  // bluer: the Cz channel, whose CSF is the widest
    FlipResult r = flip(a, b, 67, 2);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            bool within = std::abs(x - 30) <= 10 && std::abs(y - 20) <= 10;
            if (within) {
                EXPECT_GT(*r.error.at(x, y), 0) << x << "," << y;
            } else {
                EXPECT_EQ(*r.error.at(x, y), 0) << x << "," << y;
            }
        }
    double sum = 0;
    for (double e : r.error.pixels) sum += e;
    EXPECT_NEAR(r.mean, sum / (64 * 48), 1e-15);
}

// An image equal to the reference in its left half: the right half's errors
// have the bits they have when the images differ everywhere (skipping the
// equal columns cannot change how the others are computed).
TEST(Flip, EqualPartsChangeNothingInTheComparedParts) {
    Image8 a = pattern_image(90, 70), blurred = box_blur(a, 1), right = a;
    for (int y = 0; y < 70; ++y) std::copy(blurred.at(45, y), blurred.at(90, y), right.at(45, y));
    FlipResult everywhere = flip(a, blurred, 67, 2), half = flip(prepare_flip_reference(a), right, 1);
    for (int y = 0; y < 70; ++y)
        for (int x = 0; x < 90; ++x) {
            if (x >= 45 + 10) {
                EXPECT_EQ(*half.error.at(x, y), *everywhere.error.at(x, y)) << x << "," << y;
            } else if (x < 45 - 10) {
                EXPECT_EQ(*half.error.at(x, y), 0) << x << "," << y;
            }
        }
}

TEST(Flip, BadInputIsRejected) {
    EXPECT_THROW(flip(pattern_image(10, 10), pattern_image(11, 10)), std::invalid_argument);
    EXPECT_THROW(flip(pattern_image(10, 10), pattern_image(10, 10), 0), std::invalid_argument);
    EXPECT_THROW(flip(prepare_flip_reference(pattern_image(10, 10)), pattern_image(10, 11)),
                 std::invalid_argument);
}

// A building of known pixels: 4 covered by the reference, 2 by the test (1 of
// them also by the reference), on a 4x2 image whose other 3 pixels differ
// too; the mean over the 5 pixels either covers, not over all 8.
TEST(Flip, CoveredMeanIsOverThePixelsEitherImageCovers) {
    Plane error(4, 2, 1);
    error.pixels = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8};
    const Coverage reference{4, 2, {1, 1, 1, 1, 0, 0, 0, 0}}, test{4, 2, {0, 0, 0, 1, 1, 0, 0, 0}};
    EXPECT_DOUBLE_EQ(covered_mean(error, reference, test), (0.1 + 0.2 + 0.3 + 0.4 + 0.5) / 5);
    const Coverage none{4, 2, std::vector<std::uint8_t>(8, 0)};
    EXPECT_EQ(covered_mean(error, none, none), 0);  // nothing drawn: nothing differs
    EXPECT_THROW(covered_mean(error, Coverage{2, 2, std::vector<std::uint8_t>(4, 1)}, test),
                 std::invalid_argument);
    // A building a quarter of the image: the whole-image mean is a quarter of the covered one.
    const Image8 white(40, 40, 3, 255);
    Image8 a = white, b = white;
    Coverage covered{40, 40, std::vector<std::uint8_t>(1600, 0)};
    for (int y = 10; y < 30; ++y)
        for (int x = 10; x < 30; ++x) {
            std::fill(a.at(x, y), a.at(x, y) + 3, 40), std::fill(b.at(x, y), b.at(x, y) + 3, 90);
            covered.covered[std::size_t(y * 40 + x)] = 1;
        }
    const FlipResult r = flip(a, b, 67, 1);
    EXPECT_GT(covered_mean(r.error, covered, covered), 3.5 * r.mean);
}
