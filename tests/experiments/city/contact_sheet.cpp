#include "experiments/city/contact_sheet.h"

#include <gtest/gtest.h>

using namespace boxlod;

TEST(ContactSheet, ShrinkAveragesBlocks) {
    Image8 image(5, 3, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            image.at(x, y)[0] = std::uint8_t(10 * x + 100 * (y % 2)), image.at(x, y)[2] = 7;
    Image8 small = shrink(image, 2);
    ASSERT_EQ(small.width, 3);
    ASSERT_EQ(small.height, 2);
    EXPECT_EQ(small.at(0, 0)[0], 55);  // (0 + 10 + 100 + 110) / 4
    EXPECT_EQ(small.at(1, 0)[0], 75);  // (20 + 30 + 120 + 130) / 4
    EXPECT_EQ(small.at(2, 0)[0], 90);  // the partial column: (40 + 140) / 2
    EXPECT_EQ(small.at(0, 1)[0], 5);   // the partial row: (0 + 10) / 2
    EXPECT_EQ(small.at(2, 1)[2], 7);
    EXPECT_EQ(shrink(image, 1).pixels, image.pixels);
}

TEST(ContactSheet, LaysTilesOnAGridWithLabels) {
    std::vector<Image8> tiles;
    for (int i = 0; i < 5; ++i) tiles.emplace_back(40, 30, 3, std::uint8_t(40 * (i + 1)));
    Image8 unlabelled = contact_sheet(tiles, {}, 3);
    ASSERT_EQ(unlabelled.width, 3 * 40 + 4 * 2);
    ASSERT_EQ(unlabelled.height, 2 * 30 + 3 * 2);
    EXPECT_EQ(unlabelled.at(2, 2)[0], 40);                        // tile 0's corner
    EXPECT_EQ(unlabelled.at(2 + 2 * 42, 2)[1], 120);              // tile 2, top right
    EXPECT_EQ(unlabelled.at(2 + 42, 2 + 32 + 29)[2], 200);        // tile 4, second row
    EXPECT_EQ(unlabelled.at(2 + 2 * 42 + 5, 2 + 32 + 5)[0], 32);  // no sixth tile: background
    EXPECT_EQ(unlabelled.at(0, 0)[0], 32);                        // the gap

    Image8 labelled = contact_sheet(tiles, {"frame 0", "frame 1", "frame 2", "frame 3", "frame 4"}, 3);
    // The label's strip is darkened and carries white text; below it the tile is untouched.
    int white = 0;
    for (int y = 2; y < 14; ++y)
        for (int x = 2; x < 42; ++x) white += labelled.at(x, y)[0] == 255;
    EXPECT_GT(white, 10);
    EXPECT_EQ(labelled.at(40, 13)[0], 10);  // 40 / 4 in the strip, right of the text
    EXPECT_EQ(labelled.at(10, 20)[0], 40);
    EXPECT_TRUE(contact_sheet({}, {}, 4).empty());
}
