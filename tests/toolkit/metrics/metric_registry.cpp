#include "toolkit/metrics/metric_registry.h"

#include "base/input_error.h"
#include "metric_images.h"
#include "test_support.h"
#include "toolkit/metrics/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boxlod;

TEST(MetricRegistry, NamesParseInTheGivenOrderEachOnce) {
    EXPECT_EQ(parse_metrics({"flip", "psnr", "flip"}, "--metric"),
              (std::vector<Metric>{Metric::flip, Metric::psnr}));
    EXPECT_EQ(all_metrics().size(), metrics().size());
    EXPECT_EQ(test::input_error_of([] {
                  parse_metrics({"psnr", "vmaf"}, "boxlod compare: --metric");
              }),
              "boxlod compare: --metric: unknown metric 'vmaf' (rmse, psnr, ssim, flip, flip_covered, iou)");
}

TEST(MetricRegistry, MeasuresWhatEachMetricsOwnFunctionGives) {
    Image8 a = test::pattern_image(64, 48), b = test::box_blur(a, 1);
    Coverage full = coverage_from_mask(test::rectangle_mask(64, 48, 0, 0, 64, 48));
    Coverage half = coverage_from_mask(test::rectangle_mask(64, 48, 0, 0, 32, 48));
    MetricPair pair{a, b, &full, &half};
    pair.pixels_per_degree = 40;
    MetricValues measured =
        measure_metrics({Metric::iou, Metric::psnr, Metric::rmse, Metric::flip, Metric::ssim}, pair);
    ASSERT_EQ(measured.values.size(), 5u);
    EXPECT_EQ(measured.values[0], 0.5);
    EXPECT_EQ(measured.values[1], psnr(a, b));
    EXPECT_EQ(measured.values[2], rmse(a, b));
    FlipResult flipped = flip(a, b, 40);
    EXPECT_EQ(measured.values[3], flipped.mean);
    EXPECT_EQ(measured.values[4], ssim(a, b));
    ASSERT_TRUE(measured.flip_error.has_value());
    EXPECT_EQ(measured.flip_error->pixels, flipped.error.pixels);
    // A prepared reference gives the same bits; identical images a PSNR of inf.
    FlipReference prepared = prepare_flip_reference(a, 40);
    pair.flip_reference = &prepared;
    EXPECT_EQ(measure_metrics({Metric::flip}, pair).values[0], flipped.mean);
    EXPECT_TRUE(std::isinf(measure_metrics({Metric::psnr}, {a, a}).values[0]));
    EXPECT_FALSE(measure_metrics({Metric::rmse}, pair).flip_error.has_value());
    // flip_covered: FLIP's error over the pixels either covers, here the whole image; over the left half
    // alone otherwise.
    EXPECT_EQ(measure_metrics({Metric::flip_covered}, pair).values[0],
              covered_mean(flipped.error, full, half));
    const MetricPair halves{a, b, &half, &half, &prepared};
    const MetricValues both = measure_metrics({Metric::flip, Metric::flip_covered}, halves);
    EXPECT_EQ(both.values[1], covered_mean(flipped.error, half, half));
    EXPECT_NE(both.values[1], both.values[0]);
    EXPECT_THROW(measure_metrics({Metric::flip_covered}, {a, b}),
                 std::logic_error);  // a caller without coverages
}
