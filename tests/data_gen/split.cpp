#include "data_gen/split.h"

#include <gtest/gtest.h>

namespace boxlod {

namespace {

using K = Size::Kind;

std::vector<double> sizes(const SplitLayout& layout) {
    std::vector<double> out;
    for (const SplitPiece& piece : layout.pieces) out.push_back(piece.size);
    return out;
}

}  // namespace

TEST(LayoutSplit, AbsoluteRelativeAndFloating) {
    SplitLayout layout =
        layout_split({{K::absolute, 2}, {K::relative, 0.25}, {K::floating, 1}, {K::floating, 3}}, 10, 100);
    ASSERT_TRUE(layout.fits);
    EXPECT_EQ(sizes(layout), (std::vector<double>{2, 2.5, 1.375, 4.125}));
    EXPECT_DOUBLE_EQ(layout.pieces[2].offset, 4.5);
    EXPECT_DOUBLE_EQ(layout.pieces[3].offset, 5.875);
}

TEST(LayoutSplit, AbsoluteOnlyLeavesTheRestEmpty) {
    SplitLayout layout = layout_split({{K::absolute, 2}, {K::absolute, 3}}, 10, 100);
    EXPECT_EQ(sizes(layout), (std::vector<double>{2, 3}));
}

TEST(LayoutSplit, TooLargeDoesNotFit) {
    SplitLayout layout = layout_split({{K::absolute, 6}, {K::absolute, 5}, {K::floating, 1}}, 10, 100);
    EXPECT_FALSE(layout.fits);
    EXPECT_DOUBLE_EQ(layout.needed, 11);
}

TEST(LayoutSplit, RepeatWithFloatingRoundsAndStretches) {
    // 10 m of ~3 m pieces: round(10 / 3) = 3 pieces of 10/3.
    SplitLayout layout = layout_split({{K::floating, 3, true}}, 10, 100);
    ASSERT_EQ(layout.pieces.size(), 3u);
    for (const SplitPiece& piece : layout.pieces) EXPECT_NEAR(piece.size, 10.0 / 3, 1e-12);
}

TEST(LayoutSplit, RepeatWithAbsoluteFloors) {
    // 1 m border each side, then as many 2.5 m pieces as fit into 8 m: 3, the rest empty.
    SplitLayout layout =
        layout_split({{K::absolute, 1}, {K::absolute, 2.5, true}, {K::absolute, 1}}, 10, 100);
    EXPECT_EQ(sizes(layout), (std::vector<double>{1, 2.5, 2.5, 2.5, 1}));
    EXPECT_EQ(layout.pieces[4].slot, 2u);
}

TEST(LayoutSplit, RepeatGroupOfSeveralSlots) {
    SplitLayout layout = layout_split({{K::floating, 1.5, true}, {K::absolute, 0.5, true}}, 8, 100);
    ASSERT_EQ(layout.pieces.size(), 8u);  // round(8 / 2) = 4 repetitions of two pieces
    EXPECT_DOUBLE_EQ(layout.pieces[0].size, 1.5);
    EXPECT_DOUBLE_EQ(layout.pieces[1].size, 0.5);
    EXPECT_EQ(layout.pieces[7].slot, 1u);
}

TEST(LayoutSplit, RepeatDropsToFitTheFixedParts) {
    // round(7 / 4.5) = 2, but the group's absolute 4 m cannot repeat twice beside 3 m in 10 m.
    SplitLayout layout =
        layout_split({{K::absolute, 3}, {K::absolute, 4, true}, {K::floating, 0.5, true}}, 10, 100);
    ASSERT_TRUE(layout.fits);
    ASSERT_EQ(layout.pieces.size(), 3u);
    EXPECT_DOUBLE_EQ(layout.pieces[2].size, 3);
}

TEST(LayoutSplit, PieceLimit) {
    SplitLayout layout = layout_split({{K::floating, 0.001, true}}, 1000, 50);
    EXPECT_EQ(layout.pieces.size(), 50u);
}

}  // namespace boxlod
