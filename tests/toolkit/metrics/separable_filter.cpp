#include "toolkit/metrics/separable_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace boxlod;

namespace {
Plane ramp_plane(int width, int height) {
    Plane p(width, height, 1);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            *p.at(x, y) = std::sin(0.37 * x) + 0.01 * y * y - 0.5 * ((x * 7 + y * 3) % 5);
    return p;
}
}  // namespace

TEST(SeparableFilter, SampledGaussianIsNormalizedSymmetricAndGaussian) {
    std::vector<double> g = sampled_gaussian(1.5, 5);
    ASSERT_EQ(g.size(), 11u);
    EXPECT_NEAR(std::accumulate(g.begin(), g.end(), 0.0), 1.0, 1e-15);
    for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(g[i], g[10 - i]);
    EXPECT_NEAR(g[5 + 2] / g[5], std::exp(-4 / (2 * 1.5 * 1.5)), 1e-15);
}

TEST(SeparableFilter, ImpulseResponseIsTheOuterProductOfTheKernels) {
    Plane impulse(21, 17, 1);
    *impulse.at(10, 8) = 1;
    SeparableKernel kernel{{1, 2, 3}, {0.5, -1, 4, 2, 0.25}};
    Plane out = filter_separable(impulse, kernel, 1);
    for (int y = 0; y < 17; ++y)
        for (int x = 0; x < 21; ++x) {
            // Convolution as written: out(x) = sum_i h[i] in(x + i - r), so the impulse at 10 shows h
            // mirrored.
            int i = 10 - x + 1, j = 8 - y + 2;
            double expected =
                (i >= 0 && i < 3 && j >= 0 && j < 5) ? kernel.horizontal[i] * kernel.vertical[j] : 0;
            EXPECT_DOUBLE_EQ(*out.at(x, y), expected) << x << "," << y;
        }
}

TEST(SeparableFilter, BordersReplicateTheEdgePixels) {
    Plane step(6, 3, 1);
    for (int y = 0; y < 3; ++y) *step.at(0, y) = 6, *step.at(5, y) = 12;
    SeparableKernel kernel{{0.25, 0.5, 0.25}, {1}};
    Plane out = filter_separable(step, kernel, 1);
    EXPECT_DOUBLE_EQ(*out.at(0, 1), 0.25 * 6 + 0.5 * 6 + 0.25 * 0);  // the left neighbour is pixel 0 again
    EXPECT_DOUBLE_EQ(*out.at(5, 2), 0.25 * 0 + 0.5 * 12 + 0.25 * 12);
    EXPECT_DOUBLE_EQ(*out.at(2, 0), 0);
}

TEST(SeparableFilter, ConstantImagesStayConstantUpToRounding) {
    Plane flat(9, 40, 1, 0.7);
    std::vector<double> g = sampled_gaussian(3.0, 12);  // wider than the image
    Plane out = filter_separable(flat, {g, g}, 2);
    for (double v : out.pixels) EXPECT_NEAR(v, 0.7, 1e-15);
}

TEST(SeparableFilter, SameBitsForAnyThreadCount) {
    Plane in = ramp_plane(97, 61);
    SeparableKernel kernel{sampled_gaussian(2.0, 7), sampled_gaussian(0.8, 3)};
    Plane one = filter_separable(in, kernel, 1);
    for (int threads : {2, 3, 8})
        EXPECT_EQ(filter_separable(in, kernel, threads).pixels, one.pixels) << threads;
}

// FLIP filters only the columns where two images differ: any part of a row,
// at either edge or inside, with a kernel wider than the part, must have the
// bits the whole row has there.
TEST(SeparableFilter, PartOfARowHasTheBitsOfTheWholeRow) {
    Plane in = ramp_plane(53, 19);
    SeparableKernel kernel{sampled_gaussian(3.0, 9), sampled_gaussian(1.5, 4)};
    Plane whole = filter_separable(in, kernel, 1);
    std::vector<double> scratch, row(53, -1.0);
    for (int y : {0, 7, 18})
        for (auto [begin, end] :
             {std::pair{0, 53}, std::pair{0, 5}, std::pair{50, 53}, std::pair{10, 40}, std::pair{3, 4}}) {
            std::fill(row.begin(), row.end(), -1.0);
            filter_separable_row(in, kernel, y, begin, end, scratch, row.data());
            for (int x = 0; x < 53; ++x)
                EXPECT_EQ(row[std::size_t(x)], x >= begin && x < end ? *whole.at(x, y) : -1.0)
                    << y << ": " << x;
        }
}

TEST(SeparableFilter, EvenKernelsAreRejected) {
    EXPECT_THROW(filter_separable(Plane(4, 4, 1), {{0.5, 0.5}, {1}}, 1), std::invalid_argument);
}
