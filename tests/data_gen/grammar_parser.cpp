#include "data_gen/grammar_parser.h"

#include "base/input_error.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace boxlod {

namespace {

// The message of the InputError that parsing `text` throws ("" if none).
std::string parse_error(const std::string& text) {
    try {
        parse_grammar(text, "g.grammar");
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST(GrammarParser, RulesAttributesAndParameters) {
    Grammar g = parse_grammar(
        "# a comment\nattr h = 3 * 2\nLot --> extrude(h) Mass(1, h)\n"
        "Mass(a, b) --> i(box) // another comment\n",
        "g.grammar", "somewhere");
    EXPECT_EQ(g.file, "g.grammar");
    EXPECT_EQ(g.directory, "somewhere");
    ASSERT_EQ(g.attributes.size(), 1u);
    EXPECT_EQ(g.attributes[0].name, "h");
    ASSERT_EQ(g.rules.size(), 2u);
    EXPECT_EQ(g.rules[0].symbol, "Lot");
    EXPECT_EQ(g.rules[0].place.line, 3);
    const Sequence& lot = g.rules[0].alternatives[0].body;
    ASSERT_EQ(lot.size(), 2u);
    EXPECT_EQ(lot[0].kind, Operation::Kind::extrude);
    EXPECT_EQ(lot[1].kind, Operation::Kind::symbol);
    EXPECT_EQ(lot[1].name, "Mass");
    EXPECT_EQ(lot[1].arguments.size(), 2u);
    EXPECT_EQ(lot[1].place.column, 20);
    EXPECT_EQ(g.rules[1].parameters, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(g.find("Mass"), &g.rules[1]);
    EXPECT_EQ(g.find("Nope"), nullptr);
}

TEST(GrammarParser, SplitWithSizesAndRepeatGroup) {
    Grammar g = parse_grammar(
        "F --> split(y) { 4 : G | { ~3 : H | '0.1 : NIL }* | 1 : G }\nG --> NIL\nH --> NIL\n", "g.grammar");
    const Operation& split = g.rules[0].alternatives[0].body[0];
    EXPECT_EQ(split.kind, Operation::Kind::split);
    EXPECT_EQ(split.name, "y");
    ASSERT_EQ(split.entries.size(), 3u);
    EXPECT_EQ(split.entries[0].size.kind, Size::Kind::absolute);
    ASSERT_EQ(split.entries[1].repeated.size(), 2u);
    EXPECT_EQ(split.entries[1].repeated[0].size.kind, Size::Kind::floating);
    EXPECT_EQ(split.entries[1].repeated[1].size.kind, Size::Kind::relative);
    EXPECT_EQ(split.entries[1].repeated[1].successor[0].kind, Operation::Kind::nil);
}

TEST(GrammarParser, ComponentSplitPushAndScopeOperations) {
    Grammar g = parse_grammar(
        "M --> comp(f) { front : [ t(0, '0.5, 1) s('1, 2, 0) r(0, 90, 0) center(xz) ] | side : NIL }\n",
        "g.grammar");
    const Operation& comp = g.rules[0].alternatives[0].body[0];
    EXPECT_EQ(comp.kind, Operation::Kind::component);
    ASSERT_EQ(comp.entries.size(), 2u);
    EXPECT_EQ(comp.entries[0].selector, FaceSelector::front);
    const Operation& push = comp.entries[0].successor[0];
    ASSERT_EQ(push.kind, Operation::Kind::push);
    ASSERT_EQ(push.body.size(), 4u);
    EXPECT_EQ(push.body[0].arguments[1].kind, Size::Kind::relative);
    EXPECT_EQ(push.body[1].kind, Operation::Kind::scale);
    EXPECT_EQ(push.body[2].kind, Operation::Kind::rotate);
    EXPECT_EQ(push.body[3].name, "xz");
}

TEST(GrammarParser, InsertsAndAppearance) {
    Grammar g = parse_grammar(
        "A --> material(brick) color(\"#ff8000\") color(1, 0.5, 0) texture(wood) i(cylinder, 8) "
        "i(\"door.obj\")\n",
        "g.grammar");
    const Sequence& ops = g.rules[0].alternatives[0].body;
    ASSERT_EQ(ops.size(), 6u);
    EXPECT_EQ(ops[0].name, "brick");
    EXPECT_TRUE(ops[1].name_is_text);
    EXPECT_EQ(ops[2].arguments.size(), 3u);
    EXPECT_EQ(ops[3].kind, Operation::Kind::texture);
    EXPECT_EQ(ops[4].name, "cylinder");
    EXPECT_EQ(ops[4].arguments.size(), 1u);
    EXPECT_TRUE(ops[5].name_is_text);
    EXPECT_EQ(ops[5].name, "door.obj");
}

TEST(GrammarParser, StochasticAndConditionalAlternatives) {
    Grammar g = parse_grammar(
        "W --> 30% : i(box) | 50% : i(quad)\n  | else : NIL\nF(n) --> case n > 2 : W | else : NIL\n",
        "g.grammar");
    const Rule& w = g.rules[0];
    ASSERT_EQ(w.alternatives.size(), 3u);
    EXPECT_EQ(w.alternatives[0].kind, Alternative::Kind::probability);
    EXPECT_EQ(w.alternatives[1].percent, 50);
    EXPECT_EQ(w.alternatives[2].kind, Alternative::Kind::otherwise);
    EXPECT_EQ(g.rules[1].alternatives[0].kind, Alternative::Kind::condition);
}

TEST(GrammarParser, EmptyRuleBody) {
    Grammar g = parse_grammar("A --> B C\nB -->\nC --> NIL\n", "g.grammar");
    EXPECT_TRUE(g.rules[1].alternatives[0].body.empty());
}

TEST(GrammarParser, SyntaxErrorsNameThePlaceAndWhatWasExpected) {
    EXPECT_EQ(parse_error("A --> split(y) { 1 : B \nB --> NIL\n"), "g.grammar:2:1: expected '}', found 'B'");
    EXPECT_EQ(parse_error("A --> extrude(3\n"),
              "g.grammar:2:1: expected ',' or ')', found the end of the file");
    EXPECT_EQ(parse_error("A -> B\n"),
              "g.grammar:1:1: expected a rule 'Symbol --> operations' or 'attr name = value', found 'A'");
    EXPECT_EQ(parse_error("A --> t(1, 2)\n"), "g.grammar:1:7: t takes 3 arguments, got 2");
    EXPECT_EQ(parse_error("A --> i(sphere)\n"),
              "g.grammar:1:9: unknown primitive 'sphere' (known: box, quad, cylinder, gable, hip; put asset "
              "files in quotes)");
    EXPECT_EQ(parse_error("A --> split(w) { 1 : NIL }\n"), "g.grammar:1:7: split needs one axis: x, y or z");
    EXPECT_EQ(parse_error("A --> comp(f) { roof : NIL }\n"),
              "g.grammar:1:17: unknown face selector 'roof' (known: front, back, left, right, top, bottom, "
              "side, vertical, horizontal, all)");
    EXPECT_EQ(parse_error("A --> color(\"red\")\n"), "g.grammar:1:13: expected a colour \"#rrggbb\"");
    EXPECT_EQ(parse_error("A --> i(\"x.obj)\n"),
              "g.grammar:1:9: unterminated string (expected '\"' on the same line)");
    EXPECT_EQ(parse_error("A --> $\n"), "g.grammar:1:7: unexpected character '$'");
    EXPECT_EQ(parse_error(""), "g.grammar:1:1: the grammar has no rules");
}

TEST(GrammarParser, NestingDeeperThanTheLimitIsRefusedNotOverflowed) {
    const std::string refused = "nested more than 200 levels deep";
    auto deep = [](const std::string& open, const std::string& middle, const std::string& close, int n) {
        std::string text;
        for (int i = 0; i < n; ++i) text += open;
        text += middle;
        for (int i = 0; i < n; ++i) text += close;
        return text;
    };
    EXPECT_NE(parse_error("A --> extrude(" + deep("(", "1", ")", 3000) + ")\n").find(refused),
              std::string::npos);
    EXPECT_NE(parse_error("A --> " + deep("[ ", "NIL", " ]", 3000) + "\n").find(refused), std::string::npos);
    EXPECT_NE(parse_error("A --> " + deep("split(y) { 1 : ", "NIL", " }", 3000) + "\n").find(refused),
              std::string::npos);
    EXPECT_NE(parse_error("A --> extrude(" + deep("-", "1", "", 3000) + ")\n").find(refused),
              std::string::npos);
    std::string chain = "1";
    for (int i = 0; i < 5000; ++i) chain += " + 1";
    EXPECT_NE(parse_error("A --> extrude(" + chain + ")\n").find(refused), std::string::npos);
    // Real grammars stay far below the limit.
    EXPECT_EQ(
        parse_error("A --> extrude(" + deep("(", "1", ")", 50) + ") " + deep("[ ", "NIL", " ]", 50) + "\n"),
        "");
}

TEST(GrammarParser, MeaningErrors) {
    EXPECT_EQ(parse_error("A --> B\n"), "g.grammar:1:7: unknown symbol 'B' (no rule 'B --> ...')");
    EXPECT_EQ(parse_error("A --> B(1)\nB --> NIL\n"), "g.grammar:1:7: B takes 0 argument(s), got 1");
    EXPECT_EQ(parse_error("A --> extrude(h)\n"), "g.grammar:1:15: unknown variable 'h'");
    EXPECT_EQ(parse_error("attr a = scope.sx\nA --> NIL\n"), "g.grammar:1:10: unknown variable 'scope.sx'");
    EXPECT_EQ(parse_error("A --> extrude(foo(1))\n"), "g.grammar:1:15: unknown function 'foo'");
    EXPECT_EQ(parse_error("A --> extrude(min(1))\n"), "g.grammar:1:15: min takes 2 argument(s), got 1");
    EXPECT_EQ(parse_error("A --> NIL\nA --> NIL\n"),
              "g.grammar:2:1: a second rule for 'A' (one rule per symbol; use alternatives)");
    EXPECT_EQ(parse_error("A --> material(gold)\n").substr(0, 41),
              "g.grammar:1:16: unknown material 'gold' (");
    EXPECT_EQ(parse_error("A --> 60% : NIL | 50% : NIL\n"),
              "g.grammar:1:1: the probabilities of 'A' add up to more than 100%");
    EXPECT_EQ(parse_error("A --> else : NIL | 50% : NIL\n"),
              "g.grammar:1:7: 'else' cannot start an operation");
    EXPECT_EQ(parse_error("A --> 50% : NIL | i(box)\n"),
              "g.grammar:1:19: expected an alternative: 'N% :', 'case condition :' or 'else :', found 'i'");
    EXPECT_EQ(parse_error("A(n) --> case n > 1 : NIL | else : NIL | case n > 0 : NIL\n"),
              "g.grammar:1:29: 'else' must be the last alternative");
    EXPECT_EQ(parse_error("split --> NIL\n"), "g.grammar:1:1: 'split' is a reserved word, not a symbol name");
}

TEST(GrammarParser, ReadGrammarResolvesAssetsBesideTheFile) {
    auto folder = test::scratch_folder("read_grammar");
    test::write_text(folder / "a.grammar", "A --> i(box)\n");
    Grammar g = read_grammar((folder / "a.grammar").string());
    EXPECT_EQ(g.directory, folder.string());
    EXPECT_THROW(read_grammar((folder / "missing.grammar").string()), InputError);
}

}  // namespace boxlod
