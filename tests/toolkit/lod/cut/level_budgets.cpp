#include "toolkit/lod/cut/level_budgets.h"

#include <gtest/gtest.h>

using namespace boxlod;

TEST(LevelBudgets, ReadsFractionsAndSizesAndWritesThemBack) {
    std::vector<ByteBudget> budgets;
    ASSERT_EQ(parse_budgets("0.5,0.25,0.1,0.05", budgets), "");
    ASSERT_EQ(budgets.size(), 4u);
    EXPECT_TRUE(budgets[2].fraction);
    EXPECT_EQ(budgets[2].value, 0.1);
    EXPECT_EQ(budget_bytes(budgets[1], 1000), 250);
    EXPECT_EQ(format_budgets(budgets), "0.5,0.25,0.1,0.05");

    ASSERT_EQ(parse_budgets("2MB,500kB,1KiB,3B", budgets), "");
    ASSERT_EQ(budgets.size(), 4u);
    EXPECT_FALSE(budgets[0].fraction);
    EXPECT_EQ(budgets[0].value, 2e6);
    EXPECT_EQ(budgets[2].value, 1024);
    EXPECT_EQ(budget_bytes(budgets[1], 1000), 5e5);  // a size ignores the original's bytes
    std::vector<ByteBudget> again;
    ASSERT_EQ(parse_budgets(format_budgets(budgets), again), "");
    ASSERT_EQ(again.size(), budgets.size());
    for (std::size_t i = 0; i < again.size(); ++i) EXPECT_EQ(again[i].value, budgets[i].value);

    ASSERT_EQ(parse_budgets("0.5, 0.25", budgets), "");  // spaces around items, as in sweep configs
    EXPECT_EQ(format_budgets(budgets), "0.5,0.25");
    ASSERT_EQ(parse_budgets("none", budgets), "");
    EXPECT_TRUE(budgets.empty());
    EXPECT_EQ(format_budgets(budgets), "none");
}

TEST(LevelBudgets, RefusesBudgetsThatNameNoLevels) {
    for (const char* text : {"0.1,0.5", "0.5,0.5", "0.5,0", "-0.5", "1.5", "nan", "inf", "0.5,100kB",
                             "5parsecs", "0.5,,0.1", "0.5,", "", "2e20B", "0B"}) {
        std::vector<ByteBudget> budgets = {{true, 0.5}};
        EXPECT_NE(parse_budgets(text, budgets), "") << text;
        EXPECT_EQ(budgets.size(), 1u) << text << ": a refused text leaves the budgets as they were";
    }
    std::string many;
    for (int i = 0; i < 65;
         ++i) {  // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "," + string
        if (i) many += ',';
        many += std::to_string(1000 - i);
        many += 'B';
    }
    std::vector<ByteBudget> budgets;
    EXPECT_NE(parse_budgets(many, budgets), "");
}

TEST(LevelBudgets, GeometricBudgetsRunFromTheOriginalToTheCoarsestCut) {
    const std::vector<double> budgets = geometric_budgets(10, 1000, 2);
    ASSERT_EQ(budgets.size(), 2u);
    EXPECT_NEAR(budgets[0], 100, 1e-9);
    EXPECT_NEAR(budgets[1], 10, 1e-9);
}

TEST(LevelBudgets, PrefixesWithinABudget) {
    const std::vector<double> bytes = {10, 20, 15, 40, 50}, error = {9, 5, 6, 2, 0};
    EXPECT_EQ(longest_prefix_within(bytes, 20), 2u);      // 15 bytes after two steps
    EXPECT_EQ(best_prefix_within(bytes, error, 20), 1u);  // error 5 beats 6
    EXPECT_EQ(best_prefix_within(bytes, error, 45), 3u);
    EXPECT_EQ(best_prefix_within(bytes, error, 5), 0u);  // none fits: the start
    EXPECT_EQ(longest_prefix_within(bytes, 5), 0u);
    // A start beyond the budget gives way to the first prefix within it, then to lower errors.
    const std::vector<double> dear_start = {30, 25, 10, 20}, more_error = {5, 8, 9, 7};
    EXPECT_EQ(best_prefix_within(dear_start, more_error, 20), 3u);
    EXPECT_EQ(best_prefix_within(dear_start, more_error, 15), 2u);
}
