#include "base/input_file.h"

#include "base/input_error.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {
std::string problem(const std::string& path) {
    return test::input_error_of([&] { read_input_file(path, "grammar file"); });
}
}  // namespace

TEST(InputFile, NamesEachWayAFileCanBeWrong) {
    auto folder = test::scratch_folder("input_file");
    test::write_text(folder / "g.grammar", "Lot --> NIL\n");
    EXPECT_EQ(read_input_file((folder / "g.grammar").string(), "grammar file"), "Lot --> NIL\n");
    EXPECT_EQ(problem((folder / "none.grammar").string()),
              (folder / "none.grammar").string() + ": no such file");
    EXPECT_EQ(problem(folder.string()), folder.string() + ": is a directory, not a grammar file");
    EXPECT_EQ(problem("/dev/null"), "/dev/null: is not a regular file (a grammar file was expected)");
}
