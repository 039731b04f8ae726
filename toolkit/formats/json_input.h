// JSON text read from a file (glTF, CityJSON, web-ifc's answer), checked in
// one pass before nlohmann-json parses it: nested at most max_nesting_depth
// deep (base/input_error.h), since what nlohmann-json copies or prints of a
// tree recurses, and its tree within the memory budget (base/memory_budget.h),
// since a tree takes up to some 30 times the text ("[[],[],...]").
#pragma once
#include <string>
#include <string_view>

namespace boxlod {

// An upper estimate of the bytes nlohmann-json's tree of `json` takes while
// parsed (a scan without recursion: brackets, separators and strings outside strings).
double json_tree_bytes(std::string_view json);

// Throws InputError naming `file`: "byte N: JSON nested more than ..." or
// "`what` would need N GB, more than ..." for `trees` times the tree.
void check_json_input(std::string_view json, const std::string& file, double trees = 1,
                      const std::string& what = "its JSON, parsed,");

}  // namespace boxlod
