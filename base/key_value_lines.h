// The plain-text files boxlod reads (parameter files, sweep configs): one
// `key = value` per line, `#` at a line's start or after a blank starts a
// comment (a value may hold one: FILE#OBJECT), blank lines are ignored.
#pragma once
#include <string>
#include <vector>

namespace boxlod {

struct KeyValueLine {
    int line = 0;            // 1-based, for messages
    std::string key, value;  // trimmed; value may be empty
};

// Throws InputError "file: line N: expected 'key = value'" for a line without
// '=', and "file: line N: KEY: given twice (first on line M)" for a repeated key.
std::vector<KeyValueLine> parse_key_value_lines(const std::string& text, const std::string& file);

}  // namespace boxlod
