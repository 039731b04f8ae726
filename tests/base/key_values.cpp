#include "base/key_values.h"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace boxlod;

TEST(KeyValues, NumbersPrintShortAndReadBackExactly) {
    EXPECT_EQ(format_number(3.0), "3");
    EXPECT_EQ(format_number(-0.0), "0");
    EXPECT_EQ(format_number(0.1), "0.1");
    EXPECT_EQ(format_number(0.1f), "0.1");
    for (double v : {1.0 / 3.0, 1e-300, 123456789.123456789, -2.5e17})
        EXPECT_EQ(std::strtod(format_number(v).c_str(), nullptr), v);
}

TEST(KeyValues, ValueOfFindsTheFirstEntry) {
    KeyValues entries{number_entry("a", 1), number_entry("b", 2), number_entry("a", 3)};
    EXPECT_EQ(value_of(entries, "a"), "1");
    EXPECT_EQ(value_of(entries, "b"), "2");
    EXPECT_EQ(value_of(entries, "c"), "");
}

TEST(KeyValues, LinesAndJson) {
    KeyValues entries{number_entry("nodes", 12), text_entry("name", "a \"b\"")};
    EXPECT_EQ(format_key_values(entries), "nodes = 12\nname = a \"b\"\n");
    EXPECT_EQ(format_json(entries), "{\n  \"nodes\": 12,\n  \"name\": \"a \\\"b\\\"\"\n}\n");
}

TEST(KeyValues, ACommaListKeepsEveryItemEvenEmptyOnes) {
    EXPECT_EQ(comma_list("0.5, 0.25,0.1"), (std::vector<std::string>{"0.5", "0.25", "0.1"}));
    EXPECT_EQ(comma_list("10,20,"),
              (std::vector<std::string>{"10", "20", ""}));  // a trailing comma is an empty item
    EXPECT_EQ(comma_list(",a"), (std::vector<std::string>{"", "a"}));
    EXPECT_EQ(comma_list("a,, b"), (std::vector<std::string>{"a", "", "b"}));
    EXPECT_EQ(comma_list(""), (std::vector<std::string>{""}));
    EXPECT_EQ(comma_list(" \t"), (std::vector<std::string>{""}));
}
