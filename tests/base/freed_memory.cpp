#include "base/freed_memory.h"

#include <gtest/gtest.h>

#include <malloc.h>

#include <memory>

using namespace boxlod;

// A freed block of 48 MB, above the largest mapping threshold glibc moves to
// by itself (32 MB), stays in the heap for the next allocation instead of
// going back to the system.
TEST(FreedMemory, AFreedBlockOfMegabytesStaysForTheNextAllocation) {
    if (!keep_freed_memory()) GTEST_SKIP() << "this allocator takes no mallopt settings (a sanitizer's)";
    constexpr std::size_t block = 48 << 20;
    const std::size_t free_before = mallinfo2().fordblks;
    {
        auto buffer = std::make_unique<char[]>(block);
        buffer[block - 1] = 1;
    }
    EXPECT_GE(mallinfo2().fordblks, free_before + block) << "the freed block went back to the system";
}
