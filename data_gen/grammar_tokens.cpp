#include "data_gen/grammar_tokens.h"

#include "base/utf8.h"

#include <cctype>
#include <charconv>
#include <cstdio>
#include <utility>

namespace boxlod {
namespace {

// Longest punctuation first, so "-->" is not read as "-" "-" ">".
const char* const punctuation[] = {"-->", "<=", ">=", "==", "!=", "&&", "||", "(", ")",
                                   "{",   "}",  "[",  "]",  "|",  ":",  ",",  "*", "'",
                                   "~",   "%",  "+",  "-",  "/",  "<",  ">",  "=", "!"};

// <cctype>'s tests on a char of any sign (a standard function's address is not to be taken).
bool is_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_alnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// The token starting at text[i] (no space, no comment) and the characters it spans.
std::pair<Token, std::size_t> read_token(const std::string& text, std::size_t i, SourcePlace place,
                                         const std::string& file) {
    Token token;
    token.place = place;
    const char c = text[i];
    if (is_alpha(c) || c == '_') {
        std::size_t end = i;
        while (end < text.size() && (is_alnum(text[end]) || text[end] == '_' || text[end] == '.')) ++end;
        token.kind = Token::Kind::identifier;
        token.text = text.substr(i, end - i);
        return {token, end - i};
    }
    if (is_digit(c) || (c == '.' && i + 1 < text.size() && is_digit(text[i + 1]))) {
        auto [end, error] = std::from_chars(text.data() + i, text.data() + text.size(), token.number);
        if (error == std::errc::result_out_of_range)
            throw_grammar_error(file, place, "a number beyond what a double holds (or nearer 0 than it can)");
        if (error != std::errc()) throw_grammar_error(file, place, "malformed number");
        token.kind = Token::Kind::number;
        token.text = text.substr(i, std::size_t(end - (text.data() + i)));
        return {token, token.text.size()};
    }
    if (c == '"') {
        std::size_t end = text.find_first_of("\"\n", i + 1);
        if (end == std::string::npos || text[end] != '"')
            throw_grammar_error(file, place, "unterminated string (expected '\"' on the same line)");
        token.kind = Token::Kind::text;
        token.text = text.substr(i + 1, end - i - 1);
        return {token, end + 1 - i};
    }
    for (const char* p : punctuation)
        if (text.compare(i, std::char_traits<char>::length(p), p) == 0) {
            token.kind = Token::Kind::punctuation;
            token.text = p;
            return {token, token.text.size()};
        }
    if (static_cast<unsigned char>(c) >= 0x80) {  // names are ASCII: name the whole UTF-8 character
        std::size_t end = i + 1;
        while (end < text.size() && end < i + 4 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80)
            ++end;
        char byte[8];
        std::snprintf(byte, sizeof byte, "\\x%02X", static_cast<unsigned char>(c));
        const std::string character = is_utf8(text.substr(i, end - i)) ? text.substr(i, end - i) : byte;
        throw_grammar_error(
            file, place,
            "unexpected character '" + character + "' (names are ASCII letters, digits and '_')");
    }
    throw_grammar_error(file, place, std::string("unexpected character '") + c + "'");
}

}  // namespace

std::vector<Token> tokenize(const std::string& text, const std::string& file) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    SourcePlace place{1, 1};
    auto advance = [&](std::size_t n) {
        for (std::size_t k = 0; k < n && i < text.size(); ++k, ++i) {
            if (text[i] == '\n')
                place = {place.line + 1, 1};
            else
                ++place.column;
        }
    };
    while (i < text.size()) {
        if (is_space(text[i])) {
            advance(1);
        } else if (text[i] == '#' || text.compare(i, 2, "//") == 0) {
            while (i < text.size() && text[i] != '\n') advance(1);
        } else {
            auto [token, length] = read_token(text, i, place, file);
            tokens.push_back(std::move(token));
            advance(length);
        }
    }
    Token end;
    end.place = place;
    tokens.push_back(end);
    return tokens;
}

std::string describe(const Token& token) {
    switch (token.kind) {
    case Token::Kind::end: return "the end of the file";
    case Token::Kind::text: return "\"" + token.text + "\"";
    default: return "'" + token.text + "'";
    }
}

}  // namespace boxlod
