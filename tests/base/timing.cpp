#include "base/timing.h"

#include <gtest/gtest.h>

#include <thread>

using namespace boxlod;

// A scoped timer adds its scope's seconds to what its total already held.
TEST(ScopedTimer, AddsEachScopesSecondsToItsTotal) {
    double total = 1;
    {
        const ScopedTimer timer(total);
        EXPECT_EQ(total, 1);  // nothing added before the scope ends
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_GE(total, 1.02);
    const double after_one = total;
    {
        const ScopedTimer timer(total);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_GE(total, after_one + 0.02);
}
