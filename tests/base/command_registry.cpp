#include "base/command_registry.h"

#include "base/input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <new>
#include <stdexcept>

using namespace boxlod;

namespace {
int ran = 0;
std::vector<Subcommand> commands() {
    return {
        {{"echo", "", "Echo. Second sentence.", {{"times", "N", "how often", NumberRange{1, 3}}}, 0, 0},
         [](const Arguments& a) { return ran = a.integer("times", 1), 0; }},
        {{"bad", "", "Bad input.", {}, 0, 0},
         [](const Arguments&) -> int { throw InputError("x.txt: line 2: wrong"); }},
        {{"broken", "", "A bug.", {}, 0, 0}, [](const Arguments&) -> int { throw std::logic_error("oops"); }},
        {{"greedy", "", "More than there is.", {}, 0, 0},
         [](const Arguments&) -> int { throw std::bad_alloc(); }}};
}
int run(std::vector<const char*> words) {
    words.insert(words.begin(), "boxlod");
    return run_subcommands(commands(), int(words.size()), const_cast<char**>(words.data()));
}
}  // namespace

TEST(CommandRegistry, RunsTheNamedSubcommandWithItsParsedOptions) {
    EXPECT_EQ(run({"echo", "--times", "3"}), 0);
    EXPECT_EQ(ran, 3);
}

TEST(CommandRegistry, ExitStatusIsTwoForBadInputAndUsageAndOneForABug) {
    testing::internal::CaptureStderr();
    EXPECT_EQ(run({"bad"}), 2);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "boxlod: x.txt: line 2: wrong\n");
    testing::internal::CaptureStderr();
    EXPECT_EQ(run({"echo", "--times", "9"}), 2);  // out of the option's range
    EXPECT_EQ(run({"nonsense"}), 2);
    EXPECT_EQ(run({}), 2);  // no command: the overview, as usage
    testing::internal::GetCapturedStderr();
    testing::internal::CaptureStderr();
    EXPECT_EQ(run({"broken"}), 1);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "boxlod: internal error: oops\n");
}

// A request the memory budget's estimate let through, yet more than the machine gives, is refused as
// too large (exit 2, one line), not reported as a bug.
TEST(CommandRegistry, RunningOutOfMemoryIsOneLineAndExitStatusTwo) {
    testing::internal::CaptureStderr();
    EXPECT_EQ(run({"greedy"}), 2);
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << said;
    EXPECT_NE(said.find("out of memory"), std::string::npos) << said;
}

TEST(CommandRegistry, TheOverviewListsEachCommandsFirstSentence) {
    testing::internal::CaptureStdout();
    EXPECT_EQ(run({"--help"}), 0);
    std::string overview = testing::internal::GetCapturedStdout();
    EXPECT_NE(overview.find("  echo       Echo.\n"), std::string::npos) << overview;
    EXPECT_EQ(overview.find("Second sentence"), std::string::npos);
}
