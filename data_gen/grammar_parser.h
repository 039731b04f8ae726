// Reads the grammar language (data_gen/README.md) into a Grammar and checks
// it: every symbol has a rule, calls match the rules' parameters, variables,
// functions, primitives, materials and selectors exist. Errors are one line,
// "file:line:column: what was expected".
#pragma once
#include "data_gen/grammar.h"

#include <string>

namespace boxlod {

// `file` names the grammar in messages; assets are found relative to `directory`.
Grammar parse_grammar(const std::string& text, const std::string& file, const std::string& directory = "");

// Reads and parses a grammar file; a missing file is an InputError.
Grammar read_grammar(const std::string& path);

}  // namespace boxlod
