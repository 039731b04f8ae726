#include "toolkit/atlas.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

std::vector<Eigen::Vector2i> faces(int count, int seed) {
    std::vector<Eigen::Vector2i> sizes;
    std::uint32_t state = std::uint32_t(seed) * 2654435761u + 1;
    for (int i = 0; i < count; ++i) {
        state = state * 1664525u + 1013904223u;
        int w = 1 + int(state >> 24) % 60;
        state = state * 1664525u + 1013904223u;
        int h = 1 + int(state >> 24) % 40;
        sizes.emplace_back(w, h);
    }
    return sizes;
}

// No overlap (gutters included), inside the page, gutter kept from the page border.
void expect_valid(const Atlas& atlas, const std::vector<Eigen::Vector2i>& sizes, int gutter) {
    ASSERT_EQ(atlas.placements.size(), sizes.size());
    EXPECT_EQ(atlas.page_size & (atlas.page_size - 1), 0) << "page size is a power of two";
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        const AtlasPlacement& a = atlas.placements[i];
        ASSERT_GE(a.page, 0);
        ASSERT_LT(a.page, atlas.pages);
        EXPECT_GE(a.x - gutter, 0);
        EXPECT_GE(a.y - gutter, 0);
        EXPECT_LE(a.x + sizes[i].x() + gutter, atlas.page_size);
        EXPECT_LE(a.y + sizes[i].y() + gutter, atlas.page_size);
        for (std::size_t j = i + 1; j < sizes.size(); ++j) {
            const AtlasPlacement& b = atlas.placements[j];
            if (a.page != b.page) continue;
            bool apart = a.x + sizes[i].x() + 2 * gutter <= b.x || b.x + sizes[j].x() + 2 * gutter <= a.x ||
                         a.y + sizes[i].y() + 2 * gutter <= b.y || b.y + sizes[j].y() + 2 * gutter <= a.y;
            ASSERT_TRUE(apart) << "faces " << i << " and " << j << " closer than two gutters";
        }
    }
}

}  // namespace

TEST(Atlas, SmallSetFitsOnePageOfTheSmallestSize) {
    std::vector<Eigen::Vector2i> sizes = faces(10, 1);
    Atlas atlas = pack_atlas(sizes, 64, 4096, 2);
    expect_valid(atlas, sizes, 2);
    EXPECT_EQ(atlas.pages, 1);
    EXPECT_LE(atlas.page_size, 256);
}

TEST(Atlas, PageSizeDoublesUntilOnePageHoldsEverything) {
    std::vector<Eigen::Vector2i> sizes = faces(300, 2);
    Atlas atlas = pack_atlas(sizes, 64, 4096, 2);
    expect_valid(atlas, sizes, 2);
    EXPECT_EQ(atlas.pages, 1);
    // Half the size would not have held them in one page.
    EXPECT_GT(pack_atlas(sizes, atlas.page_size / 2, atlas.page_size / 2, 2).pages, 1);
}

TEST(Atlas, AtTheLargestSizeAsManyPagesAsNeeded) {
    std::vector<Eigen::Vector2i> sizes = faces(300, 3);
    Atlas atlas = pack_atlas(sizes, 32, 128, 2);
    expect_valid(atlas, sizes, 2);
    EXPECT_EQ(atlas.page_size, 128);
    EXPECT_GT(atlas.pages, 3);
}

TEST(Atlas, PackingIsDeterministic) {
    std::vector<Eigen::Vector2i> sizes = faces(200, 4);
    Atlas a = pack_atlas(sizes, 64, 512, 2), b = pack_atlas(sizes, 64, 512, 2);
    ASSERT_EQ(a.pages, b.pages);
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        EXPECT_EQ(a.placements[i].page, b.placements[i].page);
        EXPECT_EQ(a.placements[i].x, b.placements[i].x);
        EXPECT_EQ(a.placements[i].y, b.placements[i].y);
    }
}

TEST(Atlas, NoFacesGiveNoPages) {
    Atlas atlas = pack_atlas({}, 64, 512, 2);
    EXPECT_EQ(atlas.pages, 0);
    EXPECT_EQ(atlas.page_size, 64);
}
