#include "toolkit/selection/strategy_text.h"

#include "base/input_error.h"

#include <gtest/gtest.h>

#include <string>

using namespace boxlod;

namespace {

// The InputError message of parsing `text`, "" when it parses.
std::string error_of(const std::string& text) {
    try {
        parse_strategy(text, "--strategy");
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST(StrategyText, ParsesEveryStrategyWithItsParameters) {
    Strategy distance = parse_strategy("distance:40,80,160", "--strategy");
    ASSERT_TRUE(std::holds_alternative<DistanceBands>(distance));
    EXPECT_EQ(std::get<DistanceBands>(distance).distances, (std::vector<double>{40, 80, 160}));

    Strategy pixels = parse_strategy("pixels:200000,5e4,10000", "--strategy");
    ASSERT_TRUE(std::holds_alternative<PixelCount>(pixels));
    EXPECT_EQ(std::get<PixelCount>(pixels).pixels, (std::vector<double>{200000, 50000, 10000}));

    Strategy ratio = parse_strategy("ratio:0.2,0.05,0.01", "--strategy");
    ASSERT_TRUE(std::holds_alternative<ScreenRatio>(ratio));
    EXPECT_EQ(std::get<ScreenRatio>(ratio).ratios, (std::vector<double>{0.2, 0.05, 0.01}));

    BoxDiagonal diagonal = std::get<BoxDiagonal>(parse_strategy("diagonal:8,300,square-root", "--strategy"));
    EXPECT_EQ(diagonal.min_pixels, 8);
    EXPECT_EQ(diagonal.max_pixels, 300);
    EXPECT_EQ(diagonal.interpolation, DiagonalInterpolation::square_root);
    BoxDiagonal defaults = std::get<BoxDiagonal>(parse_strategy("diagonal", "--strategy"));
    EXPECT_EQ(defaults.min_pixels, 16);
    EXPECT_EQ(defaults.max_pixels, 512);
    EXPECT_EQ(defaults.interpolation, DiagonalInterpolation::linear);
    EXPECT_EQ(std::get<BoxDiagonal>(parse_strategy("diagonal:1,2,square", "x")).interpolation,
              DiagonalInterpolation::square);

    EXPECT_FALSE(std::get<TexelExact>(parse_strategy("texel", "--strategy")).error_budget);
    EXPECT_EQ(std::get<TexelExact>(parse_strategy("texel:0.05", "--strategy")).error_budget, 0.05);

    EXPECT_EQ(std::get<MeasuredSwitch>(parse_strategy("measured", "--strategy")).error, 0.05);
    EXPECT_EQ(std::get<MeasuredSwitch>(parse_strategy("measured:0.1", "--strategy")).error, 0.1);
}

TEST(StrategyText, FormatParsesBackToTheSameText) {
    for (const char* text : {"distance:40,80,160", "pixels:2e+05,50000,10000", "ratio:0.2,0.05,0.01",
                             "diagonal:16,512,linear", "diagonal:8,300,square-root", "diagonal:1,2,square",
                             "texel", "texel:0.05", "measured:0.1", "distance:0.1,0.30000000000000004"}) {
        Strategy strategy = parse_strategy(text, "--strategy");
        EXPECT_EQ(format_strategy(strategy), text);
        EXPECT_EQ(format_strategy(parse_strategy(format_strategy(strategy), "again")), text);
    }
    EXPECT_EQ(format_strategy(parse_strategy("diagonal", "x")), "diagonal:16,512,linear");
    EXPECT_EQ(format_strategy(parse_strategy("pixels:200000,50000,10000", "x")), "pixels:2e+05,50000,10000");
    EXPECT_EQ(strategy_name(parse_strategy("distance:1", "x")), "distance");
    EXPECT_EQ(strategy_name(parse_strategy("pixels:1", "x")), "pixels");
    EXPECT_EQ(strategy_name(parse_strategy("ratio:1", "x")), "ratio");
    EXPECT_EQ(strategy_name(parse_strategy("diagonal", "x")), "diagonal");
    EXPECT_EQ(strategy_name(parse_strategy("texel:1", "x")), "texel");
    EXPECT_EQ(strategy_name(parse_strategy("measured", "x")), "measured");
    EXPECT_EQ(format_strategy(parse_strategy("measured", "x")), "measured:0.05");
}

TEST(StrategyText, BadTextIsOneErrorNamingWhere) {
    EXPECT_EQ(error_of("distance:40,80,160"), "");
    for (const char* text : {"sideways",
                             "",
                             "distance",
                             "distance:",
                             "distance:40,,80",
                             "distance:40,abc",
                             "distance:80,40",
                             "pixels:10,20",
                             "ratio:0.1,0.1",
                             "pixels:-5",
                             "distance:nan",
                             "diagonal:16",
                             "diagonal:16,512,cubic",
                             "diagonal:600,500",
                             "diagonal:1,2,linear,4",
                             "texel:",
                             "texel:-1",
                             "texel:0.1,0.2",
                             "distance:40 ,80",
                             "measured:0",
                             "measured:1.5",
                             "measured:1e-9",  // below what build's --switch-error takes
                             "measured:0.1,0.2",
                             "measured:nan"}) {
        std::string message = error_of(text);
        EXPECT_EQ(message.rfind("--strategy: ", 0), 0u) << "'" << text << "' gave '" << message << "'";
        EXPECT_EQ(message.find('\n'), std::string::npos);
    }
    EXPECT_NE(error_of("sideways").find("unknown strategy 'sideways'"), std::string::npos);
    EXPECT_NE(error_of("distance:80,40").find("increase"), std::string::npos);
    EXPECT_NE(error_of("pixels:10,20").find("decrease"), std::string::npos);
    EXPECT_NE(error_of("diagonal:16,512,cubic").find("cubic"), std::string::npos);
}
