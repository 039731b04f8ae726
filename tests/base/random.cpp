#include "base/random.h"

#include <gtest/gtest.h>

#include <set>

namespace boxlod {

// The reference output of O'Neill's pcg32-demo for pcg32_srandom(42, 54).
TEST(Pcg32, MatchesTheReferenceImplementation) {
    Pcg32 random(42, 54);
    for (std::uint32_t expected :
         {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u, 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu})
        EXPECT_EQ(random.next_uint(), expected);
}

TEST(Pcg32, StreamsDiffer) {
    Pcg32 a(7, 1), b(7, 2);
    EXPECT_NE(a.next_uint(), b.next_uint());
}

TEST(Pcg32, UniformStaysInItsRange) {
    Pcg32 random(1, 1);
    for (int i = 0; i < 1000; ++i) {
        double u = random.uniform(2, 3);
        EXPECT_GE(u, 2);
        EXPECT_LT(u, 3);
    }
}

TEST(HashCombine, ChildIdentitiesAreDistinct) {
    std::set<std::uint64_t> seen;
    for (std::uint64_t parent = 0; parent < 30; ++parent)
        for (std::uint64_t child = 0; child < 30; ++child) seen.insert(hash_combine(parent, child));
    EXPECT_EQ(seen.size(), 900u);
}

}  // namespace boxlod
