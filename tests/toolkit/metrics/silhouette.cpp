#include "toolkit/metrics/silhouette.h"

#include "metric_images.h"

#include <gtest/gtest.h>

using namespace boxlod;
using namespace boxlod::test;

TEST(Silhouette, HalfOverlappingRectanglesHaveIouOneThird) {
    // 40x20 rectangles shifted by 20: intersection 20x20 = 400, union 60x20 = 1200.
    Coverage a = coverage_from_mask(rectangle_mask(80, 40, 10, 10, 50, 30));
    Coverage b = coverage_from_mask(rectangle_mask(80, 40, 30, 10, 70, 30));
    EXPECT_DOUBLE_EQ(silhouette_iou(a, b), 400.0 / 1200.0);
    EXPECT_DOUBLE_EQ(silhouette_iou(b, a), 400.0 / 1200.0);
    EXPECT_EQ(covered_pixels(a), 800u);
}

TEST(Silhouette, IdenticalDisjointAndEmptyMasks) {
    Coverage a = coverage_from_mask(rectangle_mask(30, 30, 2, 2, 9, 9));
    Coverage far = coverage_from_mask(rectangle_mask(30, 30, 20, 20, 25, 25));
    Coverage empty = coverage_from_mask(rectangle_mask(30, 30, 0, 0, 0, 0));
    EXPECT_EQ(silhouette_iou(a, a), 1.0);
    EXPECT_EQ(silhouette_iou(a, far), 0.0);
    EXPECT_EQ(silhouette_iou(empty, empty), 1.0);
    EXPECT_EQ(silhouette_iou(a, empty), 0.0);
}

TEST(Silhouette, MaskThresholdIsAbove127) {
    Image8 mask(2, 1, 4, 255);
    mask.at(0, 0)[0] = 127;
    mask.at(1, 0)[0] = 128;
    Coverage c = coverage_from_mask(mask);
    EXPECT_EQ(c.covered, (std::vector<std::uint8_t>{0, 1}));
}

TEST(Silhouette, ColourImagesAreCoveredWhereTheyDifferFromTheBackground) {
    Image8 image = flat_image(3, 1, 255, 255, 255);
    image.at(1, 0)[2] = 254;  // one channel off by one
    image.at(2, 0)[0] = 0;
    Coverage c = coverage_from_background(image, {255, 255, 255});
    EXPECT_EQ(c.covered, (std::vector<std::uint8_t>{0, 1, 1}));
    EXPECT_EQ(coverage_from_background(image, {0, 255, 255}).covered, (std::vector<std::uint8_t>{1, 1, 0}));
}

TEST(Silhouette, DifferentSizesAreRejected) {
    EXPECT_THROW(silhouette_iou(coverage_from_mask(Image8(3, 3, 1)), coverage_from_mask(Image8(3, 4, 1))),
                 std::invalid_argument);
}
