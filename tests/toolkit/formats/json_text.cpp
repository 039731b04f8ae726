#include "toolkit/formats/json_text.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

using namespace boxlod;

namespace {

std::string number_text(double value) {
    JsonText j;
    j.number(value);
    return j.text;
}

}  // namespace

// nlohmann's layout over the shortest digits that read back.
TEST(JsonText, NumbersAsNlohmannLaysThemOut) {
    EXPECT_EQ(number_text(3), "3.0");
    EXPECT_EQ(number_text(-0.0), "-0.0");
    EXPECT_EQ(number_text(0.1), "0.1");
    EXPECT_EQ(number_text(0.21500002f), "0.21500001847743988");  // a float's double: the digits it needs
    EXPECT_EQ(number_text(1e-4), "0.0001");
    EXPECT_EQ(number_text(1e-5), "1e-05");
    EXPECT_EQ(number_text(123456789012345.0), "123456789012345.0");
    EXPECT_EQ(number_text(1e15), "1e+15");
    EXPECT_EQ(number_text(-2.5e300), "-2.5e+300");
    EXPECT_EQ(number_text(std::numeric_limits<double>::quiet_NaN()), "null");
}

TEST(JsonText, CompactWithEscapesAndKeysInOrder) {
    JsonText j;
    j.begin_object();
    j.key("a");
    j.begin_array();
    j.integer(1);
    j.string("tab\t\"quote\" \x01");
    j.boolean(true);
    j.null();
    j.end_array();
    j.key("b");
    j.raw("{\"x\":1}");
    j.end_object();
    EXPECT_EQ(j.text, R"({"a":[1,"tab\t\"quote\" \u0001",true,null],"b":{"x":1}})");
}

// Misuse is a programming error, not a broken file.
TEST(JsonText, RefusesWhatWouldNotBeJsonOrNotInNlohmannsOrder) {
    JsonText out_of_order;
    out_of_order.begin_object();
    out_of_order.key("b");
    out_of_order.integer(1);
    EXPECT_THROW(out_of_order.key("a"), std::logic_error);
    JsonText key_in_array;
    key_in_array.begin_array();
    EXPECT_THROW(key_in_array.key("a"), std::logic_error);
    EXPECT_THROW(key_in_array.end_object(), std::logic_error);
    JsonText value_without_key;
    value_without_key.begin_object();
    EXPECT_THROW(value_without_key.integer(1), std::logic_error);
    JsonText not_utf8;
    EXPECT_THROW(not_utf8.string("\xff"), std::logic_error);
}
