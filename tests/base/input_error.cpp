#include "base/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

using namespace boxlod;

TEST(InputError, RangesAndCheckedArithmeticHoldAtTheEdges) {
    EXPECT_TRUE(range_fits(8, 8, 16));
    EXPECT_FALSE(range_fits(8, 9, 16));
    EXPECT_FALSE(range_fits(SIZE_MAX - 7, 16, 16));  // would wrap to 8 when added
    EXPECT_FALSE(range_fits(17, 0, 16));
    std::size_t product = 0;
    EXPECT_TRUE(checked_multiply(1u << 20, 1u << 20, product));
    EXPECT_EQ(product, std::size_t(1) << 40);
    EXPECT_FALSE(checked_multiply(SIZE_MAX / 2, 3, product));
    EXPECT_TRUE((NumberRange{1, 2}).contains(2));
    EXPECT_FALSE((NumberRange{1, 2}).contains(std::nan("")));
    EXPECT_EQ(out_of_range_message({0.1, 179}, "720"), "expected a number in [0.1, 179], got '720'");
}

TEST(InputError, AMessageIsOnePrintableLine) {
    using namespace std::string_literals;
    EXPECT_STREQ(InputError("f.json: CityObjects 'a\0b\x1b[31m': no geometry\n"s).what(),
                 "f.json: CityObjects 'a\\x00b\\x1b[31m': no geometry");
    EXPECT_EQ(input_message("f.gltf", "node 'a\r\nb'", "bad\x7f"), "f.gltf: node 'a  b': bad\\x7f");
    EXPECT_STREQ(InputError("tab\tstays, UTF-8 too: W\xc3\xa4nde").what(),
                 "tab\tstays, UTF-8 too: W\xc3\xa4nde");
    // A message quoting megabytes of a file is cut, never inside a character.
    const std::string long_line =
        InputError(std::string(9999, 'a') + "\xc3\xa4" + std::string(1000000, 'b')).what();
    EXPECT_EQ(long_line, std::string(9999, 'a') + "\xc3\xa4 ... (1010001 bytes in all)");
}
