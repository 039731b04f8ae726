#include "base/number_text.h"

#include <gtest/gtest.h>
#include <cstdint>

using namespace boxlod;

TEST(NumberText, TheWholeTextOrNothing) {
    double value = 0;
    EXPECT_TRUE(read_whole("1e-3", value));
    EXPECT_EQ(value, 1e-3);
    EXPECT_TRUE(read_whole("inf", value));  // finite_number refuses it
    for (const char* text : {"", " 1", "1 ", "+1", "1,5", "0x10", "12abc", "-"})
        EXPECT_FALSE(read_whole(text, value)) << text;
    std::uint64_t count = 0;
    EXPECT_FALSE(read_whole("-1", count));
    EXPECT_FALSE(read_whole("1.5", count));
    EXPECT_FALSE(read_whole("18446744073709551616", count));  // 2^64
}

TEST(NumberText, FiniteNumbersOnly) {
    EXPECT_EQ(finite_number<double>("-2.5"), -2.5);
    for (const char* text : {"inf", "-inf", "nan", "1e999"})
        EXPECT_FALSE(finite_number<double>(text)) << text;
    EXPECT_FALSE(finite_number<float>("1e39"));  // beyond a float
    EXPECT_EQ(finite_number<int>("-7"), -7);
    EXPECT_FALSE(finite_number<int>("2147483648"));
}

// A float is checked as written: the float nearest 0.01 lies below 0.01, and
// a range whose minimum is 0.01 must take "0.01".
TEST(NumberText, RangeCheckedOnTheNumberWritten) {
    constexpr NumberRange range{0.01, 100};
    ASSERT_LT(double(0.01f), 0.01);
    EXPECT_EQ(number_within<float>("0.01", range), 0.01f);
    EXPECT_EQ(number_within<float>("100", range), 100.0f);
    EXPECT_FALSE(number_within<float>("100.0001", range));
    EXPECT_FALSE(number_within<float>("0.00999", range));
    EXPECT_FALSE(number_within<float>("nan", range));
    EXPECT_EQ(number_within<int>("3", NumberRange{1, 3}), 3);
    EXPECT_FALSE(number_within<int>("4", NumberRange{1, 3}));
    EXPECT_FALSE(number_within<int>("2.0", NumberRange{1, 3}));
}

TEST(NumberText, AProblemSaysWhatWasExpected) {
    constexpr NumberRange range{0, 10000};
    EXPECT_EQ(number_problem<int>("12", range), "");
    EXPECT_EQ(number_problem<int>("1e3", range), "expected a whole number in [0, 10000], got '1e3'");
    EXPECT_EQ(number_problem<int>("20000", range), "expected a number in [0, 10000], got '20000'");
    EXPECT_EQ(number_problem<int>("99999999999", range),
              "expected a number in [0, 10000], got '99999999999'");
    EXPECT_EQ(number_problem<int>("0.5", range), "expected a whole number in [0, 10000], got '0.5'");
    EXPECT_EQ(number_problem<double>("wide", range), "expected a number in [0, 10000], got 'wide'");
}

// A number the field cannot hold is refused, not read as 0 (--distance 1e-46 sized for the framing
// distance) or inf.
TEST(NumberText, AFloatTooSmallOrTooLargeForItsFieldIsRefused) {
    constexpr NumberRange any{0, 1e300};
    EXPECT_EQ(number_within<float>("0", any), 0.0f);
    EXPECT_EQ(number_within<float>("1e-30", any), 1e-30f);
    EXPECT_FALSE(number_within<float>("1e-46", any));
    EXPECT_FALSE(number_within<float>("1e39", any));
    EXPECT_TRUE(number_within<double>("1e39", any));
    EXPECT_EQ(number_problem<float>("1e-46", any),
              "expected 0 or a number of magnitude in [1.2e-38, 3.4e+38], got '1e-46'");
    EXPECT_EQ(number_problem<double>("1e-310", any),
              "expected 0 or a number of magnitude in [2.2e-308, 1.8e+308], got '1e-310'");
    // Outside the range, the range is what was expected (0 is not in it either).
    EXPECT_EQ(number_problem<float>("1e-46", NumberRange{0.1, 179}),
              "expected a number in [0.1, 179], got '1e-46'");
}
