#include "data_gen/grammar_tokens.h"

#include "base/input_error.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <string>

using namespace boxlod;

TEST(GrammarTokens, CutsTextIntoWordsWithTheirPlaces) {
    const std::vector<Token> tokens =
        tokenize("Lot --> s(1.5, .5) # a comment\n  wall.x \"red\" // another\n-->", "g");
    std::vector<std::string> texts;
    for (const Token& t : tokens) texts.push_back(t.text);
    EXPECT_EQ(texts, (std::vector<std::string>{"Lot", "-->", "s", "(", "1.5", ",", ".5", ")", "wall.x", "red",
                                               "-->", ""}));
    EXPECT_EQ(tokens[4].kind, Token::Kind::number);
    EXPECT_EQ(tokens[6].number, 0.5);
    EXPECT_EQ(tokens[9].kind, Token::Kind::text);
    EXPECT_EQ(tokens[8].place.line, 2);
    EXPECT_EQ(tokens[8].place.column, 3);
    EXPECT_EQ(tokens[10].place.line, 3);
    EXPECT_EQ(tokens.back().kind, Token::Kind::end);
    EXPECT_EQ(describe(tokens[9]), "\"red\"");
    EXPECT_EQ(describe(tokens.back()), "the end of the file");
}

TEST(GrammarTokens, RefusesWhatNoTokenStartsWithAtItsPlace) {
    auto message = [](const std::string& text) {
        return test::input_error_of([&] { tokenize(text, "g.grammar"); });
    };
    EXPECT_NE(message("a\n  \"open").find("g.grammar:2:3"), std::string::npos) << message("a\n  \"open");
    EXPECT_NE(message("a\n  \"open").find("unterminated string"), std::string::npos);
    EXPECT_NE(message("a $").find("unexpected character '$'"), std::string::npos);
    // One character, not its first byte (which made the line invalid UTF-8); a stray byte as \xHH.
    EXPECT_EQ(message("a \xD0\x97\xD0\xB4"),
              "g.grammar:1:3: unexpected character '\xD0\x97' (names are ASCII letters, digits and '_')");
    EXPECT_EQ(message("a \xFF"),
              "g.grammar:1:3: unexpected character '\\xFF' (names are ASCII letters, digits and '_')");
    EXPECT_EQ(message("a 1e400"),
              "g.grammar:1:3: a number beyond what a double holds (or nearer 0 than it can)");
}
