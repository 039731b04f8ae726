// A parsed shape grammar (data_gen/README.md describes the language): rules
// `Symbol(parameters) --> operations`, global attributes, and the place in the
// source of everything, so errors found while deriving can point at it.
#pragma once
#include "base/enum_table.h"

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace boxlod {

struct SourcePlace {
    int line = 0, column = 0;
};

// "file:line:column: what", one line: how every grammar error reads.
std::string grammar_message(const std::string& file, SourcePlace place, const std::string& what);
[[noreturn]] void throw_grammar_error(const std::string& file, SourcePlace place, const std::string& what);

struct Expression {
    enum class Kind { number, variable, unary, binary, call };
    Kind kind = Kind::number;
    double value = 0;                  // number
    std::string name;                  // variable, function or operator ("-", "+", "<=", "&&", "!")
    std::vector<Expression> operands;  // unary, binary, call arguments
    SourcePlace place;
};

// A size in a split or a t/s argument: absolute metres, 'relative to the
// scope, or ~floating (stretched to fill what the others leave).
struct Size {
    enum class Kind { absolute, relative, floating };
    Kind kind = Kind::absolute;
    Expression value;
};

// The faces of a scope a component split's entry takes: one by name, or
// side (left and right), vertical (all but top and bottom), horizontal, all.
enum class FaceSelector { front, back, left, right, top, bottom, side, vertical, horizontal, all };
std::span<const EnumEntry<FaceSelector>> face_selectors();
bool selects(FaceSelector selector, const std::string& face);  // face: a scope face's name ("front", ...)

struct Operation;
using Sequence = std::vector<Operation>;

// One entry of a split or component split. Either `size : sequence` (split),
// `selector : sequence` (comp), or a repeated group `{ entries }*` (split).
struct SplitEntry {
    Size size;
    std::optional<FaceSelector> selector;  // comp entries
    Sequence successor;
    std::vector<SplitEntry> repeated;  // non-empty: this entry is a repeat group
    SourcePlace place;
};

struct Operation {
    enum class Kind {
        symbol,     // name(arguments): apply the rule `name`, a child node
        nil,        // NIL: the shape disappears
        extrude,    // extrude([axis,] height)
        split,      // split(axis) { entries }
        component,  // comp(f) { selector : sequence | ... }
        translate,  // t(x, y, z)
        rotate,     // r(x, y, z) degrees
        scale,      // s(x, y, z)
        center,     // center(axes)
        insert,     // i(primitive [, segments]) or i("asset file")
        material,   // material(name)
        texture,    // texture(name)
        color,      // color(r, g, b) or color("#rrggbb")
        push,       // [ sequence ]: the scope and appearance come back afterwards
    };
    Kind kind = Kind::symbol;
    std::string name;  // symbol, axis letters, primitive, asset path, material, texture or colour text
    bool name_is_text = false;  // name was a "quoted string" (an asset file, a colour)
    std::vector<Size> arguments;
    std::vector<SplitEntry> entries;  // split, component
    Sequence body;                    // push
    SourcePlace place;
};

// The operations called by name, each with its syntax as help (NIL, '[' and
// rule symbols are not in it).
std::span<const EnumEntry<Operation::Kind>> operation_kinds();

// One way a rule can go: always, with a probability (percent), or when a
// condition holds (`case`), or `else`.
struct Alternative {
    enum class Kind { always, probability, condition, otherwise };
    Kind kind = Kind::always;
    double percent = 0;
    Expression condition;
    Sequence body;
    SourcePlace place;
};

struct Rule {
    std::string symbol;
    std::vector<std::string> parameters;
    std::vector<Alternative> alternatives;
    SourcePlace place;
};

struct Attribute {
    std::string name;
    Expression value;
    SourcePlace place;
};

struct Grammar {
    std::string file;                   // names the grammar in every message
    std::string directory;              // where asset paths are resolved ("" = working directory)
    std::vector<Attribute> attributes;  // evaluated in order, each may use the earlier ones
    std::vector<Rule> rules;            // rules[0] is the default start symbol
    std::map<std::string, std::size_t> rule_index;

    const Rule* find(const std::string& symbol) const {
        auto it = rule_index.find(symbol);
        return it == rule_index.end() ? nullptr : &rules[it->second];
    }
};

}  // namespace boxlod
