#include "toolkit/lod/pages/atlas.h"

#include <gtest/gtest.h>
#include "base/random.h"

using namespace boxlod;

namespace {

std::vector<Eigen::Vector2i> faces(int count, int seed, int max_width = 60, int max_height = 40) {
    std::vector<Eigen::Vector2i> sizes;
    Pcg32 random(std::uint64_t(seed), 1);
    for (int i = 0; i < count; ++i) {
        int w = 1 + int(random.next_uint() % std::uint32_t(max_width));
        int h = 1 + int(random.next_uint() % std::uint32_t(max_height));
        sizes.emplace_back(w, h);
    }
    return sizes;
}

bool power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

// Power-of-two pages within the limits; every face inside its page; two faces on a
// page at least two gutters apart (a face may touch the page's border).
void expect_valid(const Atlas& atlas, const std::vector<Eigen::Vector2i>& sizes, int min_size, int max_size,
                  int gutter) {
    ASSERT_EQ(atlas.placements.size(), sizes.size());
    for (const Eigen::Vector2i& page : atlas.pages) {
        EXPECT_TRUE(power_of_two(page.x()) && power_of_two(page.y())) << page.transpose();
        EXPECT_TRUE(page.minCoeff() >= min_size && page.maxCoeff() <= max_size) << page.transpose();
    }
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        const AtlasPlacement& a = atlas.placements[i];
        ASSERT_GE(a.page, 0);
        ASSERT_LT(a.page, int(atlas.pages.size()));
        const Eigen::Vector2i page = atlas.pages[std::size_t(a.page)], block = placed_size(sizes[i], a);
        EXPECT_GE(a.x, 0);
        EXPECT_GE(a.y, 0);
        EXPECT_LE(a.x + block.x(), page.x());
        EXPECT_LE(a.y + block.y(), page.y());
        for (std::size_t j = i + 1; j < sizes.size(); ++j) {
            const AtlasPlacement& b = atlas.placements[j];
            if (a.page != b.page) continue;
            const Eigen::Vector2i other = placed_size(sizes[j], b);
            bool apart = a.x + block.x() + 2 * gutter <= b.x || b.x + other.x() + 2 * gutter <= a.x ||
                         a.y + block.y() + 2 * gutter <= b.y || b.y + other.y() + 2 * gutter <= a.y;
            ASSERT_TRUE(apart) << "faces " << i << " and " << j << " closer than two gutters";
        }
    }
}

double occupancy(const Atlas& atlas, const std::vector<Eigen::Vector2i>& sizes) {
    double texels = 0;
    for (const Eigen::Vector2i& s : sizes) texels += double(s.x()) * s.y();
    return texels / double(page_texels(atlas));
}

}  // namespace

TEST(Atlas, SmallSetFitsSmallPages) {
    std::vector<Eigen::Vector2i> sizes = faces(10, 1);
    Atlas atlas = pack_atlas(sizes, 64, 4096, 2);
    expect_valid(atlas, sizes, 64, 4096, 2);
    EXPECT_LE(page_texels(atlas), 128u * 128u);
}

TEST(Atlas, PagesAreAnyPowerOfTwoRectangle) {
    // One 200x50 face: 256x64, not a square 256x256.
    std::vector<Eigen::Vector2i> sizes = {{200, 50}};
    Atlas atlas = pack_atlas(sizes, 32, 1024, 2);
    expect_valid(atlas, sizes, 32, 1024, 2);
    ASSERT_EQ(atlas.pages.size(), 1u);
    EXPECT_EQ(atlas.pages[0], Eigen::Vector2i(256, 64));
}

TEST(Atlas, TallFacesLieDownWhenThatPacksTighter) {
    // A wide and a tall strip: as baked they need 142 rows or columns (a 256x128
    // page); the tall one lying down, both stack into 128x64.
    std::vector<Eigen::Vector2i> sizes = {{120, 20}, {20, 120}};
    Atlas atlas = pack_atlas(sizes, 16, 1024, 2);
    expect_valid(atlas, sizes, 16, 1024, 2);
    ASSERT_EQ(atlas.pages.size(), 1u);
    EXPECT_EQ(atlas.pages[0], Eigen::Vector2i(128, 64));
    EXPECT_FALSE(atlas.placements[0].rotated);
    EXPECT_TRUE(atlas.placements[1].rotated);
    EXPECT_EQ(placed_size(sizes[1], atlas.placements[1]), Eigen::Vector2i(120, 20));
}

TEST(Atlas, AtTheLargestSizeAsManyPagesAsNeededThenSmallerOnes) {
    std::vector<Eigen::Vector2i> sizes = faces(300, 3);
    Atlas atlas = pack_atlas(sizes, 32, 128, 2);
    expect_valid(atlas, sizes, 32, 128, 2);
    EXPECT_GT(atlas.pages.size(), 3u);
    EXPECT_EQ(atlas.pages.front(), Eigen::Vector2i(128, 128));
    EXPECT_LT(atlas.pages.back().prod(), 128 * 128);  // the rest on a smaller page
}

// Occupancy on fixed inputs (face texels / page texels) with the 2-texel gutter:
// many small faces (where the gutters alone take a quarter), a few large ones, a mix;
// each bound a point or two below what the packer reaches on these PCG32 inputs.
TEST(Atlas, OccupancyOnFixedInputs) {
    std::vector<Eigen::Vector2i> many = faces(400, 5), large = faces(12, 6, 400, 300),
                                 mix = faces(200, 7, 200, 120);
    const std::vector<std::pair<std::vector<Eigen::Vector2i>, double>> cases = {
        {many, 0.70}, {large, 0.68}, {mix, 0.76}};
    for (const auto& [sizes, at_least] : cases) {
        Atlas atlas = pack_atlas(sizes, 64, 4096, 2);
        expect_valid(atlas, sizes, 64, 4096, 2);
        EXPECT_GE(occupancy(atlas, sizes), at_least)
            << sizes.size() << " faces on " << atlas.pages.size() << " pages";
    }
}

// Gutters counted inside the page only: one 200x50 face on its 256x64 page, and
// on many small faces what is neither face nor gutter (free space) stays small.
TEST(Atlas, GutterTexelsAreTheBlocksButTheFacesInsideThePage) {
    std::vector<Eigen::Vector2i> one = {{200, 50}};
    Atlas atlas = pack_atlas(one, 32, 1024, 2);
    ASSERT_EQ(atlas.pages[0], Eigen::Vector2i(256, 64));
    const AtlasPlacement at = atlas.placements[0];
    const int x0 = std::max(at.x - 2, 0), x1 = std::min(at.x + 200 + 2, 256), y0 = std::max(at.y - 2, 0),
              y1 = std::min(at.y + 50 + 2, 64);
    EXPECT_EQ(gutter_texels(atlas, one, 2), std::uint64_t((x1 - x0) * (y1 - y0) - 200 * 50));
    EXPECT_EQ(gutter_texels(atlas, one, 0), 0u);
    std::vector<Eigen::Vector2i> many = faces(400, 5);
    Atlas packed = pack_atlas(many, 64, 4096, 2);
    std::uint64_t face = 0;
    for (const Eigen::Vector2i& s : many) face += std::uint64_t(s.x()) * std::uint64_t(s.y());
    const std::uint64_t gutter = gutter_texels(packed, many, 2);
    EXPECT_GT(gutter, face / 4);  // small faces: the gutters are a large share
    EXPECT_LE(face + gutter, page_texels(packed));
    EXPECT_GE(double(face + gutter),
              0.85 * double(page_texels(packed)));  // and the packer leaves little free
}

// The same atlas for any thread count (the two layouts are packed side by side).
TEST(Atlas, PackingIsDeterministic) {
    std::vector<Eigen::Vector2i> sizes = faces(200, 4);
    Atlas a = pack_atlas(sizes, 64, 512, 2, 1), b = pack_atlas(sizes, 64, 512, 2, 2);
    ASSERT_EQ(a.pages, b.pages);
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        EXPECT_EQ(a.placements[i].page, b.placements[i].page);
        EXPECT_EQ(a.placements[i].x, b.placements[i].x);
        EXPECT_EQ(a.placements[i].y, b.placements[i].y);
        EXPECT_EQ(a.placements[i].rotated, b.placements[i].rotated);
    }
}

TEST(Atlas, AFaceLargerThanTheLargestPageIsRefused) {
    EXPECT_THROW(pack_atlas({{300, 10}}, 64, 256, 2), std::invalid_argument);
}
