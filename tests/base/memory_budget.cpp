#include "base/memory_budget.h"

#include "base/command_registry.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

using namespace boxlod;

TEST(MemoryBudget, DefaultsToHalfOfWhatTheProcessMayUse) {
    const double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
    EXPECT_GT(default_memory_budget(), 0);
    EXPECT_LE(default_memory_budget(), physical / 2);
    rlimit limit{};
    ASSERT_EQ(getrlimit(RLIMIT_AS, &limit), 0);
    if (limit.rlim_cur != RLIM_INFINITY) {
        EXPECT_LE(default_memory_budget(), double(limit.rlim_cur) / 2);
    }
    EXPECT_EQ(memory_budget(), default_memory_budget());
}

TEST(MemoryBudget, RefusesARequestOverItWithOneLineSayingWhatItNeeds) {
    test::MemoryBudgetScope scope;
    set_memory_budget(2e9);
    EXPECT_NO_THROW(check_memory("a frame", 2e9));
    try {
        check_memory("a 16384 x 16384 frame", 8.59e9);
        FAIL() << "not refused";
    } catch (const InputError& error) {
        EXPECT_STREQ(
            error.what(),
            "a 16384 x 16384 frame would need 8.59 GB, more than the memory budget of 2 GB (--max-memory)");
    }
    EXPECT_EQ(memory_text(5.36e8), "536 MB");
}

TEST(MemoryBudget, IsNeverMoreThanWhatTheProcessMayUse) {
    test::MemoryBudgetScope scope;
    set_memory_budget(1e15);  // --max-memory 1000000: a petabyte on a machine of gigabytes
    EXPECT_EQ(memory_budget(), usable_memory());
    EXPECT_THROW(check_memory("a 16384 x 16384 frame", 2 * usable_memory()), InputError);
}

TEST(MemoryBudget, EveryCommandTakesMaxMemory) {
    test::MemoryBudgetScope scope;
    double seen = 0;
    static double* out = &seen;
    const std::vector<Subcommand> commands = {
        {{"probe", "", "Probe.", {}, 0, 0}, [](const Arguments&) { return *out = memory_budget(), 0; }}};
    const char* words[] = {"boxlod", "probe", "--max-memory", "0.5"};
    EXPECT_EQ(run_subcommands(commands, 4, const_cast<char**>(words)), 0);
    EXPECT_EQ(seen, 0.5e9);
    const char* zero[] = {"boxlod", "probe", "--max-memory", "0"};
    testing::internal::CaptureStderr();
    EXPECT_EQ(run_subcommands(commands, 4, const_cast<char**>(zero)), 2);
    EXPECT_NE(testing::internal::GetCapturedStderr().find("--max-memory"), std::string::npos);
}
