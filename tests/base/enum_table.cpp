#include "base/enum_table.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {
enum class Fruit { apple, pear, plum };
constexpr EnumEntry<Fruit> fruit_table[] = {
    {Fruit::apple, "apple", "round"}, {Fruit::pear, "pear", "not round"}, {Fruit::plum, "plum", "small"}};
std::span<const EnumEntry<Fruit>> fruits() { return fruit_table; }
}  // namespace

TEST(EnumTable, NamesReadAndWriteTheTablesValues) {
    Fruit fruit = Fruit::apple;
    EXPECT_TRUE(parse_enum(fruits(), "plum", fruit));
    EXPECT_EQ(fruit, Fruit::plum);
    EXPECT_FALSE(parse_enum(fruits(), "Plum", fruit));  // names are exact
    EXPECT_EQ(fruit, Fruit::plum);                      // and a miss leaves the value
    EXPECT_EQ(enum_from_name(fruits(), "kiwi"), std::nullopt);
    EXPECT_STREQ(enum_name(fruits(), Fruit::pear), "pear");
}

TEST(EnumTable, ListsAndCyclesFollowTheTablesOrder) {
    EXPECT_EQ(enum_names(fruits()), "apple, pear, plum");
    EXPECT_EQ(enum_names(fruits(), ", ", " or "), "apple, pear or plum");
    EXPECT_EQ(next_enum(fruits(), Fruit::pear), Fruit::plum);
    EXPECT_EQ(next_enum(fruits(), Fruit::plum), Fruit::apple);
}
