#include "base/freed_memory.h"

#include <gtest/gtest.h>

#include <malloc.h>

#include <memory>

using namespace boxlod;

// A freed block of 24 MB stays in the heap for the next allocation instead of
// going back to the system, as it does by default (each test runs in a fresh
// process, whose mapping threshold is glibc's 128 kB).
TEST(FreedMemory, AFreedBlockOfMegabytesStaysForTheNextAllocation) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "ASan's allocator takes no mallopt settings";
#endif
    ASSERT_TRUE(keep_freed_memory());
    constexpr std::size_t block = 24 << 20;
    const std::size_t free_before = mallinfo2().fordblks;
    {
        auto buffer = std::make_unique<char[]>(block);
        asm volatile("" : : "r"(buffer.get()) : "memory");  // not optimised away
    }
    EXPECT_GE(mallinfo2().fordblks, free_before + block) << "the freed block went back to the system";
}
