#pragma once
// The grammar's words: names, numbers, "texts" and punctuation, each with its place in the file.

#include "data_gen/grammar.h"

#include <string>
#include <vector>

namespace boxlod {

struct Token {
    enum class Kind { identifier, number, text, punctuation, end };
    Kind kind = Kind::end;
    std::string text;  // a text's without its quotes
    double number = 0;
    SourcePlace place;
};

// The tokens of `text` and a last one of kind end; comments run from '#' or "//" to the end of the
// line. Throws InputError "file:line:column: what" on a character no token starts with, an
// unterminated text or a malformed number.
std::vector<Token> tokenize(const std::string& text, const std::string& file);

// How a message names the token: 'punctuation', "a text", the end of the file.
std::string describe(const Token& token);

}  // namespace boxlod
