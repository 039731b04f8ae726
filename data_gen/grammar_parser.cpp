#include "data_gen/grammar_parser.h"

#include "base/input_error.h"
#include "base/input_file.h"
#include "data_gen/expression.h"
#include "data_gen/grammar_tokens.h"
#include "data_gen/materials.h"
#include "data_gen/primitives.h"
#include "data_gen/textures.h"

#include <filesystem>
#include <set>

namespace boxlod {
namespace {

const std::set<std::string> keywords = {"attr", "case", "else", "NIL"};

bool reserved(const std::string& name) {
    return keywords.count(name) || enum_from_name(operation_kinds(), name);
}

class Parser {
public:
    Parser(std::vector<Token> tokens, std::string file)
        : tokens_(std::move(tokens)), file_(std::move(file)) {}

    Grammar parse() {
        Grammar grammar;
        grammar.file = file_;
        while (peek().kind != Token::Kind::end) {
            if (is_identifier("attr")) {
                grammar.attributes.push_back(parse_attribute());
            } else if (peek().kind == Token::Kind::identifier && starts_rule(position_)) {
                Rule rule = parse_rule();
                if (grammar.rule_index.count(rule.symbol))
                    throw_grammar_error(
                        file_, rule.place,
                        "a second rule for '" + rule.symbol + "' (one rule per symbol; use alternatives)");
                grammar.rule_index[rule.symbol] = grammar.rules.size();
                grammar.rules.push_back(std::move(rule));
            } else {
                fail("a rule 'Symbol --> operations' or 'attr name = value'");
            }
        }
        return grammar;
    }

private:
    std::vector<Token> tokens_;
    std::string file_;
    std::size_t position_ = 0;
    int depth_ = 0;  // nesting of blocks and expressions, so that no input can overflow the stack

    // One level deeper for as long as it lives.
    struct Deeper {
        Parser& parser;
        explicit Deeper(Parser& p) : parser(p) { p.deeper(); }
        ~Deeper() { --parser.depth_; }
    };
    void deeper() {
        if (++depth_ > max_nesting_depth) throw_grammar_error(file_, peek().place, nesting_message());
    }

    const Token& peek(std::size_t ahead = 0) const {
        return tokens_[std::min(position_ + ahead, tokens_.size() - 1)];
    }
    const Token& take() { return tokens_[std::min(position_++, tokens_.size() - 1)]; }
    bool is(const char* text) const { return peek().kind == Token::Kind::punctuation && peek().text == text; }
    bool is_identifier(const char* text) const {
        return peek().kind == Token::Kind::identifier && peek().text == text;
    }
    [[noreturn]] void fail(const std::string& expected) const {
        throw_grammar_error(file_, peek().place, "expected " + expected + ", found " + describe(peek()));
    }
    void expect(const char* text) {
        if (!is(text)) fail(std::string("'") + text + "'");
        take();
    }
    void expect_separator() {
        if (!is(",")) fail("',' or ')'");
        take();
    }
    std::string expect_identifier(const std::string& what) {
        if (peek().kind != Token::Kind::identifier) fail(what);
        return take().text;
    }

    // A rule starts with `Name -->` or `Name(...) -->`; anything else is an operation or a call.
    bool starts_rule(std::size_t at) const {
        if (tokens_[at].kind != Token::Kind::identifier) return false;
        std::size_t next = at + 1;
        if (tokens_[next].kind == Token::Kind::punctuation && tokens_[next].text == "(") {
            int depth = 0;
            for (; tokens_[next].kind != Token::Kind::end; ++next) {
                if (tokens_[next].text == "(" && tokens_[next].kind == Token::Kind::punctuation) ++depth;
                if (tokens_[next].text == ")" && tokens_[next].kind == Token::Kind::punctuation &&
                    --depth == 0)
                    break;
            }
            if (tokens_[next].kind == Token::Kind::end) return false;
            ++next;
        }
        return tokens_[next].kind == Token::Kind::punctuation && tokens_[next].text == "-->";
    }

    Attribute parse_attribute() {
        take();  // attr
        Attribute attribute;
        attribute.place = peek().place;
        attribute.name = expect_identifier("an attribute name");
        expect("=");
        attribute.value = parse_expression();
        return attribute;
    }

    Rule parse_rule() {
        Rule rule;
        rule.place = peek().place;
        rule.symbol = take().text;
        if (reserved(rule.symbol))
            throw_grammar_error(file_, rule.place,
                                "'" + rule.symbol + "' is a reserved word, not a symbol name");
        if (is("(")) {
            take();
            while (!is(")")) {
                rule.parameters.push_back(expect_identifier("a parameter name"));
                if (!is(")")) expect_separator();
            }
            take();
        }
        expect("-->");
        bool choice = (peek().kind == Token::Kind::number && peek(1).text == "%") || is_identifier("case");
        if (!choice) {
            Alternative only;
            only.place = peek().place;
            only.body = parse_sequence();
            rule.alternatives.push_back(std::move(only));
            return rule;
        }
        for (;;) {
            rule.alternatives.push_back(parse_alternative());
            if (!is("|")) break;
            take();
        }
        return rule;
    }

    Alternative parse_alternative() {
        Alternative alternative;
        alternative.place = peek().place;
        if (peek().kind == Token::Kind::number && peek(1).text == "%") {
            alternative.kind = Alternative::Kind::probability;
            alternative.percent = take().number;
            take();
        } else if (is_identifier("case")) {
            take();
            alternative.kind = Alternative::Kind::condition;
            alternative.condition = parse_expression();
        } else if (is_identifier("else")) {
            take();
            alternative.kind = Alternative::Kind::otherwise;
        } else {
            fail("an alternative: 'N% :', 'case condition :' or 'else :'");
        }
        expect(":");
        alternative.body = parse_sequence();
        return alternative;
    }

    // Operations up to '|', '}', ']', the next rule or attribute, or the end.
    Sequence parse_sequence() {
        Deeper deeper(*this);
        Sequence sequence;
        for (;;) {
            const Token& token = peek();
            if (token.kind == Token::Kind::end || is("|") || is("}") || is("]")) break;
            if (token.kind == Token::Kind::identifier && (token.text == "attr" || starts_rule(position_)))
                break;
            sequence.push_back(parse_operation());
        }
        return sequence;
    }

    // One operation: '[' sequence ']', NIL, a symbol, or an operation of
    // operation_kinds() with what its syntax reads after the name.
    Operation parse_operation() {
        Operation op;
        op.place = peek().place;
        if (is("[")) {
            take();
            op.kind = Operation::Kind::push;
            op.body = parse_sequence();
            expect("]");
            return op;
        }
        if (peek().kind != Token::Kind::identifier) fail("an operation, a symbol, '[' or '|'");
        const std::string name = take().text;
        if (name == "NIL") {
            op.kind = Operation::Kind::nil;
            return op;
        }
        if (keywords.count(name))
            throw_grammar_error(file_, op.place, "'" + name + "' cannot start an operation");
        const std::optional<Operation::Kind> kind = enum_from_name(operation_kinds(), name);
        if (!kind) {
            op.kind = Operation::Kind::symbol;
            op.name = name;
            if (is("(")) op.arguments = parse_arguments(false);
            return op;
        }
        op.kind = *kind;
        switch (op.kind) {
        case Operation::Kind::split:
        case Operation::Kind::component: parse_split_header(op); break;
        case Operation::Kind::center: parse_center_axes(op); break;
        case Operation::Kind::material:
        case Operation::Kind::texture: parse_appearance_name(op); break;
        case Operation::Kind::insert: parse_insert(op); break;
        case Operation::Kind::color:
            if (peek(1).kind == Token::Kind::text) {
                parse_colour_text(op);
                break;
            }
            [[fallthrough]];
        default: parse_numeric_arguments(op, name);
        }
        return op;
    }

    // split(axis) { entries } or comp(f) { entries }.
    void parse_split_header(Operation& op) {
        const bool split = op.kind == Operation::Kind::split;
        expect("(");
        op.name = expect_identifier(split ? "an axis x, y or z" : "'f' (faces)");
        if (split && op.name != "x" && op.name != "y" && op.name != "z")
            throw_grammar_error(file_, op.place, "split needs one axis: x, y or z");
        if (!split && op.name != "f") throw_grammar_error(file_, op.place, "comp takes 'f' (faces)");
        expect(")");
        expect("{");
        op.entries = split ? parse_split_entries(true) : parse_component_entries();
        expect("}");
    }

    void parse_center_axes(Operation& op) {
        expect("(");
        op.name = expect_identifier("axes such as x, xz or xyz");
        if (op.name.find_first_not_of("xyz") != std::string::npos)
            throw_grammar_error(file_, op.place, "center takes axes made of x, y and z");
        expect(")");
    }

    // material(name) or texture(name), a name the project knows.
    void parse_appearance_name(Operation& op) {
        const bool material = op.kind == Operation::Kind::material;
        expect("(");
        SourcePlace at = peek().place;
        op.name = expect_identifier(material ? "a material name" : "a texture name");
        bool known = material ? is_material_name(op.name) : (is_texture_name(op.name) || op.name == "none");
        if (!known)
            throw_grammar_error(
                file_, at,
                std::string("unknown ") + (material ? "material" : "texture") + " '" + op.name +
                    "' (known: " + (material ? material_names() : texture_names() + ", none") + ")");
        expect(")");
    }

    // i(primitive [, segments]) or i("asset file" [, segments]).
    void parse_insert(Operation& op) {
        expect("(");
        SourcePlace at = peek().place;
        if (peek().kind == Token::Kind::text) {
            op.name = take().text;
            op.name_is_text = true;
        } else {
            op.name = expect_identifier("a primitive (" + builtin_primitive_names() + ") or a \"file\"");
            if (!is_builtin_primitive(op.name))
                throw_grammar_error(file_, at,
                                    "unknown primitive '" + op.name + "' (known: " +
                                        builtin_primitive_names() + "; put asset files in quotes)");
        }
        if (is(",")) {
            take();
            op.arguments.push_back({Size::Kind::absolute, parse_expression()});
        }
        expect(")");
    }

    // color("#rrggbb").
    void parse_colour_text(Operation& op) {
        take();
        SourcePlace at = peek().place;
        op.name = take().text;
        op.name_is_text = true;
        if (op.name.size() != 7 || op.name[0] != '#' ||
            op.name.find_first_not_of("0123456789abcdefABCDEF", 1) != std::string::npos)
            throw_grammar_error(file_, at, "expected a colour \"#rrggbb\"");
        expect(")");
    }

    // extrude([axis,] height), t/r/s(x, y, z) (t and s may be 'relative), color(r, g, b).
    void parse_numeric_arguments(Operation& op, const std::string& name) {
        if (op.kind == Operation::Kind::extrude && peek(1).kind == Token::Kind::identifier &&
            (peek(1).text == "x" || peek(1).text == "y" || peek(1).text == "z") && peek(2).text == ",") {
            take();
            op.name = take().text;
            take();
            op.arguments.push_back({Size::Kind::absolute, parse_expression()});
            expect(")");
            return;
        }
        bool relative = op.kind == Operation::Kind::translate || op.kind == Operation::Kind::scale;
        op.arguments = parse_arguments(relative);
        std::size_t wanted = op.kind == Operation::Kind::extrude ? 1 : 3;
        if (op.arguments.size() != wanted)
            throw_grammar_error(file_, op.place,
                                name + " takes " + std::to_string(wanted) + " argument" +
                                    (wanted == 1 ? "" : "s") + ", got " +
                                    std::to_string(op.arguments.size()));
    }

    // '(' [size {',' size}] ')'; sizes may be 'relative when `relative` is set.
    std::vector<Size> parse_arguments(bool relative) {
        expect("(");
        std::vector<Size> arguments;
        while (!is(")")) {
            Size size;
            if (relative && is("'")) {
                take();
                size.kind = Size::Kind::relative;
            }
            size.value = parse_expression();
            arguments.push_back(std::move(size));
            if (!is(")")) expect_separator();
        }
        take();
        return arguments;
    }

    std::vector<SplitEntry> parse_split_entries(bool allow_repeat) {
        std::vector<SplitEntry> entries;
        bool has_repeat = false;
        for (;;) {
            SplitEntry entry;
            entry.place = peek().place;
            if (is("{")) {
                if (!allow_repeat) fail("a size (repeat groups do not nest)");
                if (has_repeat)
                    throw_grammar_error(file_, entry.place, "only one repeat group '{ ... }*' per split");
                has_repeat = true;
                take();
                entry.repeated = parse_split_entries(false);
                expect("}");
                expect("*");
            } else {
                if (is("'")) {
                    take();
                    entry.size.kind = Size::Kind::relative;
                } else if (is("~")) {
                    take();
                    entry.size.kind = Size::Kind::floating;
                }
                entry.size.value = parse_expression();
                expect(":");
                entry.successor = parse_sequence();
            }
            entries.push_back(std::move(entry));
            if (!is("|")) break;
            take();
        }
        return entries;
    }

    std::vector<SplitEntry> parse_component_entries() {
        std::vector<SplitEntry> entries;
        for (;;) {
            SplitEntry entry;
            entry.place = peek().place;
            const std::string selector =
                expect_identifier("a face selector (" + enum_names(face_selectors()) + ")");
            entry.selector = enum_from_name(face_selectors(), selector);
            if (!entry.selector)
                throw_grammar_error(
                    file_, entry.place,
                    "unknown face selector '" + selector + "' (known: " + enum_names(face_selectors()) + ")");
            expect(":");
            entry.successor = parse_sequence();
            entries.push_back(std::move(entry));
            if (!is("|")) break;
            take();
        }
        return entries;
    }

    // Precedence, loosest first: || && comparisons + - * / % unary.
    Expression parse_expression() { return parse_binary(0); }

    Expression parse_binary(int level) {
        static const std::vector<std::vector<std::string>> levels = {
            {"||"}, {"&&"}, {"<", ">", "<=", ">=", "==", "!="}, {"+", "-"}, {"*", "/", "%"}};
        if (level == int(levels.size())) return parse_unary();
        Expression left = parse_binary(level + 1);
        for (int links = 0;; ++links) {
            const Token& token = peek();
            bool matches = false;
            for (const std::string& op : levels[level])
                matches = matches || (token.kind == Token::Kind::punctuation && token.text == op);
            // "30% :" starts the next alternative, so % before ':' is not an operator.
            if (!matches || (token.text == "%" && peek(1).text == ":")) {
                depth_ -= links;
                return left;
            }
            deeper();  // a chain a + b + c is a tree as deep as it is long
            Expression e;
            e.kind = Expression::Kind::binary;
            e.place = token.place;
            e.name = take().text;
            e.operands.push_back(std::move(left));
            e.operands.push_back(parse_binary(level + 1));
            left = std::move(e);
        }
    }

    Expression parse_unary() {
        Deeper deeper(*this);
        if (is("-") || is("!")) {
            Expression e;
            e.kind = Expression::Kind::unary;
            e.place = peek().place;
            e.name = take().text;
            e.operands.push_back(parse_unary());
            return e;
        }
        if (is("+")) take();
        return parse_primary();
    }

    Expression parse_primary() {
        Expression e;
        e.place = peek().place;
        if (peek().kind == Token::Kind::number) {
            e.value = take().number;
            return e;
        }
        if (is("(")) {
            take();
            e = parse_expression();
            expect(")");
            return e;
        }
        if (peek().kind != Token::Kind::identifier) fail("a number, a name or '('");
        e.name = take().text;
        if (!is("(")) {
            e.kind = Expression::Kind::variable;
            return e;
        }
        e.kind = Expression::Kind::call;
        take();
        while (!is(")")) {
            e.operands.push_back(parse_expression());
            if (!is(")")) expect_separator();
        }
        take();
        return e;
    }
};

// The checks after parsing: every name known, every arity right.
struct Checker {
    const Grammar& grammar;
    std::set<std::string> attributes;  // those defined so far
    bool in_rule = false;              // scope.sx/sy/sz exist only inside rules

    void expression(const Expression& e, const std::vector<std::string>& parameters) const {
        if (e.kind == Expression::Kind::variable) {
            bool scope = e.name == "scope.sx" || e.name == "scope.sy" || e.name == "scope.sz";
            bool known = attributes.count(e.name) || (in_rule && scope);
            for (const std::string& p : parameters) known = known || p == e.name;
            if (!known) throw_grammar_error(grammar.file, e.place, "unknown variable '" + e.name + "'");
        }
        if (e.kind == Expression::Kind::call) {
            int arity = function_arity(e.name);
            if (arity < 0) throw_grammar_error(grammar.file, e.place, "unknown function '" + e.name + "'");
            if (arity != int(e.operands.size()))
                throw_grammar_error(grammar.file, e.place,
                                    e.name + " takes " + std::to_string(arity) + " argument(s), got " +
                                        std::to_string(e.operands.size()));
        }
        for (const Expression& operand : e.operands) expression(operand, parameters);
    }

    void sequence(const Sequence& ops, const std::vector<std::string>& parameters) const {
        for (const Operation& op : ops) {
            for (const Size& argument : op.arguments) expression(argument.value, parameters);
            for (const SplitEntry& entry : op.entries) split_entry(entry, parameters);
            sequence(op.body, parameters);
            if (op.kind != Operation::Kind::symbol) continue;
            const Rule* rule = grammar.find(op.name);
            if (!rule)
                throw_grammar_error(grammar.file, op.place,
                                    "unknown symbol '" + op.name + "' (no rule '" + op.name + " --> ...')");
            if (rule->parameters.size() != op.arguments.size())
                throw_grammar_error(grammar.file, op.place,
                                    op.name + " takes " + std::to_string(rule->parameters.size()) +
                                        " argument(s), got " + std::to_string(op.arguments.size()));
        }
    }

    void split_entry(const SplitEntry& entry, const std::vector<std::string>& parameters) const {
        if (!entry.selector && entry.repeated.empty()) expression(entry.size.value, parameters);
        sequence(entry.successor, parameters);
        for (const SplitEntry& inner : entry.repeated) split_entry(inner, parameters);
    }
};

void check(const Grammar& grammar) {
    if (grammar.rules.empty()) throw_grammar_error(grammar.file, {1, 1}, "the grammar has no rules");
    Checker checker{grammar, {}};
    for (const Attribute& attribute : grammar.attributes) {
        checker.expression(attribute.value, {});
        checker.attributes.insert(attribute.name);
    }
    checker.in_rule = true;
    for (const Rule& rule : grammar.rules) {
        double total_percent = 0;
        for (std::size_t a = 0; a < rule.alternatives.size(); ++a) {
            const Alternative& alternative = rule.alternatives[a];
            bool last = a + 1 == rule.alternatives.size();
            if (alternative.kind == Alternative::Kind::otherwise && !last)
                throw_grammar_error(grammar.file, alternative.place, "'else' must be the last alternative");
            if (a > 0 && alternative.kind != Alternative::Kind::otherwise &&
                alternative.kind != rule.alternatives[0].kind)
                throw_grammar_error(grammar.file, alternative.place,
                                    "do not mix 'N%' and 'case' alternatives in one rule");
            if (alternative.kind == Alternative::Kind::probability && alternative.percent < 0)
                throw_grammar_error(grammar.file, alternative.place, "a probability cannot be negative");
            if (alternative.kind == Alternative::Kind::probability) total_percent += alternative.percent;
            if (alternative.kind == Alternative::Kind::condition)
                checker.expression(alternative.condition, rule.parameters);
            checker.sequence(alternative.body, rule.parameters);
        }
        if (total_percent > 100 + 1e-9)
            throw_grammar_error(grammar.file, rule.place,
                                "the probabilities of '" + rule.symbol + "' add up to more than 100%");
    }
}

}  // namespace

Grammar parse_grammar(const std::string& text, const std::string& file, const std::string& directory) {
    Grammar grammar = Parser(tokenize(text, file), file).parse();
    grammar.directory = directory;
    check(grammar);
    return grammar;
}

Grammar read_grammar(const std::string& path) {
    return parse_grammar(read_input_file(path, "grammar file"), path,
                         std::filesystem::path(path).parent_path().string());
}

}  // namespace boxlod
