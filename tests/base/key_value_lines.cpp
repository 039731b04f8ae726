#include "base/key_value_lines.h"

#include "test_support.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

std::string refusal(const std::string& text) {
    return test::input_error_of([&] { parse_key_value_lines(text, "p.txt"); });
}

}  // namespace

TEST(KeyValueLines, KeysValuesCommentsAndLineNumbers) {
    const auto lines =
        parse_key_value_lines("# a comment\nwidth = 16  # sixteen\n\n\tmode=normal\r\nempty =\n", "p.txt");
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0].line, 2);
    EXPECT_EQ(lines[0].key, "width");
    EXPECT_EQ(lines[0].value, "16");
    EXPECT_EQ(lines[1].key, "mode");
    EXPECT_EQ(lines[1].value, "normal");
    EXPECT_EQ(lines[2].value, "");
    // A '#' inside a value is no comment: a city file's object.
    const auto object = parse_key_value_lines("model = district.city.json#house_3 # the third\n", "p.txt");
    EXPECT_EQ(object[0].value, "district.city.json#house_3");
}

// An editor's UTF-8 byte-order mark is no part of the first key; bytes that are no text are refused.
TEST(KeyValueLines, AByteOrderMarkIsSkippedAndBinaryRefused) {
    const auto lines = parse_key_value_lines("\xEF\xBB\xBFwidth = 16\n", "p.txt");
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].key, "width");
    EXPECT_EQ(refusal("width = 16\nheight = \x01\x02\n"), "p.txt: line 2: not text (byte 0x01)");
    EXPECT_EQ(refusal(std::string("a = 1\0b = 2\n", 12)), "p.txt: line 1: not text (byte 0x00)");
    EXPECT_EQ(refusal("a = 1\na = 2\n"), "p.txt: line 2: a: given twice (first on line 1)");
    EXPECT_EQ(refusal("no equals sign\n"), "p.txt: line 1: expected 'key = value'");
}
