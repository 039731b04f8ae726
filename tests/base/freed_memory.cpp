#include "base/freed_memory.h"

#include <gtest/gtest.h>

#include <malloc.h>

#include <memory>

using namespace boxlod;

// A block of 24 MB comes from the heap, not a mapping of its own, and freed
// it stays there for the next allocation instead of going back to the system,
// as glibc's defaults (a mapping threshold of 128 kB) would have it.
TEST(FreedMemory, AFreedBlockOfMegabytesStaysForTheNextAllocation) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "ASan's allocator takes no mallopt settings";
#endif
    ASSERT_TRUE(keep_freed_memory());
    constexpr std::size_t block = 24 << 20;
    const std::size_t mapped_before = mallinfo2().hblkhd;
    std::size_t heap_with_block = 0;
    {
        auto buffer = std::make_unique<char[]>(block);
        asm volatile("" : : "r"(buffer.get()) : "memory");  // not optimised away
        const struct mallinfo2 with_block = mallinfo2();
        EXPECT_EQ(with_block.hblkhd, mapped_before) << "the block was mapped apart from the heap";
        heap_with_block = with_block.arena;
    }
    const struct mallinfo2 after = mallinfo2();
    EXPECT_EQ(after.arena, heap_with_block) << "the heap gave the freed block back to the system";
    EXPECT_GE(after.fordblks, block);
}
