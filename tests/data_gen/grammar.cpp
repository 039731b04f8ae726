#include "data_gen/grammar.h"

#include "base/input_error.h"

#include <gtest/gtest.h>

namespace boxlod {

TEST(GrammarMessage, NamesFileLineAndColumn) {
    EXPECT_EQ(grammar_message("a.grammar", {3, 14}, "expected ')'"), "a.grammar:3:14: expected ')'");
}

TEST(GrammarMessage, StaysOnOneLine) {
    EXPECT_EQ(grammar_message("a.grammar", {1, 1}, "two\nlines"), "a.grammar:1:1: two lines");
}

TEST(GrammarMessage, ThrowsAnInputError) {
    EXPECT_THROW(throw_grammar_error("a.grammar", {1, 2}, "bad"), InputError);
}

}  // namespace boxlod
