#include "base/command_line.h"

#include <algorithm>

#include "base/input_error.h"
#include "base/number_text.h"

#include <cctype>
#include <stdexcept>

namespace boxlod {

std::string Arguments::text(const std::string& name, const std::string& fallback) const {
    if (auto it = values.find(name); it != values.end()) return it->second;
    auto declared = defaults.find(name);
    if (declared != defaults.end() && !fallback.empty())
        throw std::logic_error("option --" + name + " declares a default and is read with another");
    return declared == defaults.end() ? fallback : declared->second;
}

std::vector<Option> with_options(std::vector<Option> options, const std::vector<Option>& more) {
    for (const Option& o : more)
        if (std::none_of(options.begin(), options.end(),
                         [&](const Option& have) { return have.name == o.name; }))
            options.push_back(o);
    return options;
}

namespace {

// The option's value as given or declared, or nullptr where the reader's fallback holds.
template <typename Fallback>
const std::string* value_or_default(const Arguments& a, const std::string& name,
                                    const std::optional<Fallback>& fallback) {
    if (!a.ranges.count(name))
        throw std::logic_error("option --" + name + " is read as a number but declares no range");
    const bool declared = a.defaults.count(name) != 0;
    if (declared == fallback.has_value())
        throw std::logic_error(
            "option --" + name +
            (declared ? " declares a default and is read with another" : " has no default"));
    if (auto it = a.values.find(name); it != a.values.end()) return &it->second;
    return declared ? &a.defaults.at(name) : nullptr;
}

// The ranges and defaults a command declares; a default outside its range is the program's error.
Arguments declared_arguments(const Command& command) {
    Arguments arguments;
    for (const Option& o : command.options) {
        if (o.range) arguments.ranges[o.name] = *o.range;
        if (!o.default_value.empty()) arguments.defaults[o.name] = o.default_value;
        if (o.range && !o.default_value.empty() && !number_within<double>(o.default_value, *o.range))
            throw std::logic_error("option --" + o.name + ": default " + o.default_value +
                                   " outside its range");
    }
    return arguments;
}

}  // namespace

double Arguments::number(const std::string& name, std::optional<double> fallback) const {
    const std::string* text = value_or_default(*this, name, fallback);
    if (!text) return *fallback;
    const auto value = finite_number<double>(*text);
    if (!value) throw InputError("--" + name + ": expected a number, got '" + *text + "'");
    return *value;
}

int Arguments::integer(const std::string& name, std::optional<int> fallback) const {
    const std::string* text = value_or_default(*this, name, fallback);
    if (!text) return *fallback;
    int value = 0;
    if (!read_whole(*text, value))
        throw InputError("--" + name + ": expected an integer, got '" + *text + "'");
    return value;
}

Arguments parse_arguments(const Command& command, const std::vector<std::string>& words) {
    Arguments arguments = declared_arguments(command);
    std::string prefix = "boxlod " + command.name + ": ";
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& word = words[i];
        if (word == "--help" || word == "-h") {
            arguments.values["help"] = "";
            return arguments;
        }
        bool long_form = word.size() > 2 && word.compare(0, 2, "--") == 0;
        bool short_form =
            word.size() == 2 && word[0] == '-' && std::isalpha(static_cast<unsigned char>(word[1]));
        if (long_form || short_form) {
            std::string name = long_form ? word.substr(2) : word, value;
            if (short_form)
                for (const Option& o : command.options)
                    if (o.short_name == word[1]) name = o.name;
            std::size_t equals = name.find('=');
            bool inline_value = equals != std::string::npos;
            if (inline_value) {
                value = name.substr(equals + 1);
                name = name.substr(0, equals);
            }
            const Option* option = nullptr;
            for (const Option& o : command.options)
                if (o.name == name) option = &o;
            if (!option)
                throw InputError(prefix + "unknown option " + (short_form ? name : "--" + name) +
                                 " (see --help)");
            if (!option->value_name.empty() && !inline_value) {
                if (i + 1 >= words.size())
                    throw InputError(prefix + "--" + name + " needs a value " + option->value_name);
                value = words[++i];
            } else if (option->value_name.empty() && inline_value) {
                throw InputError(prefix + "--" + name + " takes no value");
            }
            // An empty value ('--reference-system ""', a shell variable unset) is a mistake, never a choice.
            if (!option->value_name.empty() && value.empty())
                throw InputError(prefix + "--" + name + " needs a value " + option->value_name + ", got ''");
            if (option->range) {
                if (!number_within<double>(value, *option->range))
                    throw InputError(prefix + "--" + name + ": " +
                                     out_of_range_message(*option->range, value));
            }
            arguments.values[name] = value;
        } else {
            arguments.positionals.push_back(word);
        }
    }
    std::size_t n = arguments.positionals.size();
    if (n < command.min_positionals || n > command.max_positionals)
        throw InputError(prefix + "expected " +
                         (command.arguments.empty() ? "no arguments" : command.arguments) + ", got " +
                         std::to_string(n) + " argument(s) (see --help)");
    return arguments;
}

namespace {

// An option's help names its default and range: "(default 9; range [1, 10000])";
// a default the help describes ("(default: frames the model)") takes the range in.
std::string help_with_range(const Option& o) {
    std::string notes = o.default_value.empty() ? "" : "default " + o.default_value;
    if (o.range) notes += (notes.empty() ? "" : "; ") + std::string("range ") + range_text(*o.range);
    if (notes.empty()) return o.help;
    if (o.default_value.empty() && o.help.find("(default") != std::string::npos && o.help.back() == ')')
        return o.help.substr(0, o.help.size() - 1) + "; " + notes + ")";
    return o.help + " (" + notes + ")";
}

}  // namespace

std::string help_text(const Command& command) {
    std::string out = "usage: boxlod " + command.name +
                      (command.arguments.empty() ? "" : " " + command.arguments) + " [options]\n\n" +
                      command.summary + "\n\noptions:\n";
    for (const Option& o : command.options) {
        std::string left = std::string(o.short_name ? std::string("  -") + o.short_name + ", " : "  ") +
                           "--" + o.name + (o.value_name.empty() ? "" : " " + o.value_name);
        if (left.size() < 28)
            left.resize(28, ' ');
        else
            left += "\n" + std::string(28, ' ');
        out += left + help_with_range(o) + "\n";
    }
    out += std::string("  --help") + std::string(20, ' ') + "show this help\n";
    return out;
}

}  // namespace boxlod
