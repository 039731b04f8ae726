// A small command-line parser shared by every `boxlod` subcommand: options
// are declared once and the same declaration produces --help.
#pragma once
#include "base/input_error.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace boxlod {

// Seeds are the non-negative ints.
constexpr NumberRange seed_range{0, 2147483647};

struct Option {
    std::string name;        // without the leading "--"
    std::string value_name;  // empty: a flag without value
    std::string help;
    std::optional<NumberRange> range =
        std::nullopt;  // a numeric option's accepted values, checked while parsing
    // Its value when not given ("": none, or one the help describes), declared
    // here only: --help shows it, and Arguments reads it.
    std::string default_value = "";
    char short_name = 0;  // e.g. 'o' for -o
};

// `options` followed by those of `more` whose names it does not have yet
// (commands that combine shared option lists).
std::vector<Option> with_options(std::vector<Option> options, const std::vector<Option>& more);

struct Command {
    std::string name;
    std::string arguments;  // e.g. "MODEL"
    std::string summary;
    std::vector<Option> options;
    std::size_t min_positionals = 0, max_positionals = 0;
};

struct Arguments {
    std::vector<std::string> positionals;
    std::map<std::string, std::string> values;    // flags map to ""
    std::map<std::string, NumberRange> ranges;    // of every numeric option declared
    std::map<std::string, std::string> defaults;  // of every option declared with a default value

    // An option not given reads as its declared default, else as `fallback`;
    // number() and integer() read only options declared with a range, and a
    // fallback for an option that declares a default, or neither, is a
    // programming error (std::logic_error): each default is written once.
    bool has(const std::string& name) const { return values.count(name) != 0; }
    std::string text(const std::string& name, const std::string& fallback = "") const;
    double number(const std::string& name, std::optional<double> fallback = std::nullopt) const;
    int integer(const std::string& name, std::optional<int> fallback = std::nullopt) const;
};

// Throws InputError ("boxlod NAME: ...") on an unknown option, a missing value,
// a number outside its option's range or a wrong number of positional arguments. `--help` is returned as a
// flag.
Arguments parse_arguments(const Command& command, const std::vector<std::string>& words);
std::string help_text(const Command& command);

}  // namespace boxlod
