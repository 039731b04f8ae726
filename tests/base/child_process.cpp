#include "base/child_process.h"

#include "test_support.h"

#include <gtest/gtest.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <thread>
#include <vector>

using namespace boxlod;

namespace {

int touched_by_the_child = 0;

std::string message_of(const std::function<std::string()>& work, ChildLimits limits = {}) {
    return test::input_error_of([&] { run_in_child(work, limits, "f.ifc", "the reader"); });
}

}  // namespace

TEST(ChildProcess, TheChildsBytesComeBackAndItsChangesStayInIt) {
    const std::string bytes("scene\0with\0zeros", 16);
    EXPECT_EQ(run_in_child(
                  [&] {
                      touched_by_the_child = 1;
                      return bytes;
                  },
                  {}, "f.ifc", "the reader"),
              bytes);
    EXPECT_EQ(touched_by_the_child, 0);
    const std::string large(5'000'000, 'x');  // more than a pipe holds at once
    EXPECT_EQ(run_in_child([&] { return large; }, {}, "f.ifc", "the reader"), large);
}

// boxlod waits for interrupts with them blocked; a reader forked so must still stop on SIGTERM, and it
// dies with boxlod (a hostile-input run found an interrupted boxlod's importer spinning for ever).
TEST(ChildProcess, TheChildTakesSignalsAndDiesWithItsParent) {
    sigset_t terminate, before;
    sigemptyset(&terminate);
    sigaddset(&terminate, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &terminate, &before);
    const std::string answer = run_in_child(
        [] {
            sigset_t mask;
            pthread_sigmask(SIG_SETMASK, nullptr, &mask);
            int death_signal = 0;
            prctl(PR_GET_PDEATHSIG, &death_signal);
            return std::to_string(sigismember(&mask, SIGTERM)) + " " + std::to_string(death_signal);
        },
        {}, "f.ifc", "the reader");
    pthread_sigmask(SIG_SETMASK, &before, nullptr);
    EXPECT_EQ(answer, "0 " + std::to_string(SIGKILL));
}

TEST(ChildProcess, AnInputErrorComesBackAsItWasAndOtherErrorsAsInternal) {
    EXPECT_EQ(message_of([]() -> std::string { throw_input_error("f.ifc", "line 3", "bad entity"); }),
              "f.ifc: line 3: bad entity");
    EXPECT_THROW(
        run_in_child([]() -> std::string { throw std::logic_error("a bug"); }, {}, "f.ifc", "the reader"),
        std::runtime_error);
}

// What the child cannot survive becomes one line naming the file and the reader.
TEST(ChildProcess, ACrashAnAbortOrATimeoutIsOneLineNamingFileAndReader) {
    EXPECT_EQ(message_of([]() -> std::string {
                  std::raise(SIGSEGV);
                  return "";
              }),
              "f.ifc: the reader crashed on this file (Segmentation fault)");
    EXPECT_EQ(message_of([]() -> std::string { std::abort(); }),
              "f.ifc: the reader crashed on this file (Aborted)");
    EXPECT_EQ(message_of([]() -> std::string { ::_exit(3); }),
              "f.ifc: the reader ended without an answer (exit status 3)");
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(message_of(
                  []() -> std::string {
                      std::this_thread::sleep_for(std::chrono::seconds(30));
                      return "";
                  },
                  {0, 0.2}),
              "f.ifc: the reader took longer than 0.2 s; stopped");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST(ChildProcess, MemoryBeyondTheAllowanceIsRefused) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer needs unlimited address space";
#endif
    const std::string message = message_of(
        [] {
            std::vector<char> huge(std::size_t(4) << 30, 1);
            return std::string(1, huge.back());
        },
        {std::size_t(64) << 20, 60});
    EXPECT_EQ(message, "f.ifc: reading it would take more than 64 MiB (counts in the file too large?)");
}

// web-ifc's node reserves far more address space than it uses, so its resident memory is what is limited.
TEST(ChildProcess, AProgramHoldingMoreThanItsResidentMemoryIsStopped) {
    const ChildLimits limits{0, 60, 100e6};
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(test::input_error_of([&] {
                  run_program_in_child({"python3", "-"},
                                       "import time\nheld = b'x' * (400 << 20)\ntime.sleep(30)\n", limits,
                                       "f.ifc", "the reader");
              }),
              "f.ifc: the reader grew past the memory budget of 100 MB (--max-memory); stopped");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
    EXPECT_EQ(
        run_program_in_child({"python3", "-"}, "import os\nheld = b'x' * (20 << 20)\nos.write(3, b'ok')\n",
                             limits, "f.ifc", "the reader"),
        "ok");
}
