#include "data_gen/expression.h"

#include "base/input_error.h"
#include "data_gen/grammar_parser.h"

#include <gtest/gtest.h>

namespace boxlod {

namespace {

// Parses `attr value = TEXT` and evaluates it with x = 3.
double value_of(const std::string& text, std::uint64_t seed = 0) {
    Grammar grammar = parse_grammar("attr x = 3\nattr value = " + text + "\nA --> NIL\n", "test.grammar");
    VariableLookup lookup = [](const std::string& name, double& value) {
        if (name != "x") return false;
        value = 3;
        return true;
    };
    Pcg32 random(seed, 1);
    return evaluate(grammar.attributes[1].value, lookup, random, "test.grammar");
}

}  // namespace

TEST(Expression, Precedence) {
    EXPECT_DOUBLE_EQ(value_of("1 + 2 * 3"), 7);
    EXPECT_DOUBLE_EQ(value_of("(1 + 2) * 3"), 9);
    EXPECT_DOUBLE_EQ(value_of("10 - 4 - 3"), 3);
    EXPECT_DOUBLE_EQ(value_of("-x * 2"), -6);
    EXPECT_DOUBLE_EQ(value_of("7 % 4"), 3);
    EXPECT_DOUBLE_EQ(value_of("8 / 2 / 2"), 2);
}

TEST(Expression, ComparisonsAndLogic) {
    EXPECT_EQ(value_of("x > 2 && x < 4"), 1);
    EXPECT_EQ(value_of("x == 2 || x != 3"), 0);
    EXPECT_EQ(value_of("!(x >= 3)"), 0);
    EXPECT_EQ(value_of("x <= 3"), 1);
}

TEST(Expression, Functions) {
    EXPECT_DOUBLE_EQ(value_of("min(x, 1) + max(x, 1)"), 4);
    EXPECT_DOUBLE_EQ(value_of("floor(2.7) + ceil(2.2) + round(2.5) + abs(-1)"), 9);
    EXPECT_DOUBLE_EQ(value_of("sqrt(16)"), 4);
    EXPECT_NEAR(value_of("sin(90) + cos(180)"), 0, 1e-12);
    EXPECT_NEAR(value_of("tan(45)"), 1, 1e-12);
}

TEST(Expression, RandIsSeededAndInRange) {
    double a = value_of("rand(2, 5)", 11), b = value_of("rand(2, 5)", 11), c = value_of("rand(2, 5)", 12);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    EXPECT_GE(a, 2);
    EXPECT_LT(a, 5);
}

TEST(Expression, NonFiniteResultIsAnError) {
    try {
        value_of("1 / (x - 3)");
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "test.grammar:2:16: the expression's value is not a finite number");
    }
}

TEST(Expression, FunctionArity) {
    EXPECT_EQ(function_arity("rand"), 2);
    EXPECT_EQ(function_arity("floor"), 1);
    EXPECT_EQ(function_arity("nope"), -1);
}

}  // namespace boxlod
