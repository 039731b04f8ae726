#include "base/common_options.h"

#include "base/input_error.h"

#include <gtest/gtest.h>

using namespace boxlod;

// Every command that takes --threads takes it with the same range, so
// `--threads 2000` is refused the same way everywhere.
TEST(CommonOptions, ThreadsAreDeclaredWithOneRange) {
    Command command{"c", "", "", {threads_option("threads for the boxes"), json_option()}, 0, 0};
    EXPECT_EQ(parse_arguments(command, {"--threads", "3"}).integer("threads", 0), 3);
    EXPECT_THROW(parse_arguments(command, {"--threads", "2000"}), InputError);
    EXPECT_EQ(threads_option("threads for the boxes").help, "threads for the boxes (default: all cores)");
}

TEST(CommonOptions, TheReportIsKeyValueLinesOrWithJsonOneObject) {
    Command command{"c", "", "", {json_option()}, 0, 0};
    const KeyValues report{number_entry("faces", 12), text_entry("output", "a.glb")};
    testing::internal::CaptureStdout();
    print_report(report, parse_arguments(command, {}));
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "faces = 12\noutput = a.glb\n");
    testing::internal::CaptureStdout();
    print_report(report, parse_arguments(command, {"--json"}));
    EXPECT_EQ(testing::internal::GetCapturedStdout(), format_json(report));
}
