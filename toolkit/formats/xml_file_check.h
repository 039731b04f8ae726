// Checks of XML files that assimp's readers do not make, run before it reads
// them: elements nested at most max_nesting_depth deep (its readers recurse
// per element), and COLLADA's arrays, accessors and node instances
// (COLLADA 1.4.1 specification, chapter 5) as it would read them.
#pragma once
#include <string>
#include <string_view>

namespace boxlod {

// XML (COLLADA, X3D): throws InputError naming `file` and the byte where
// elements nest deeper than max_nesting_depth.
void check_xml_depth(std::string_view bytes, const std::string& file);

// COLLADA: its depth as check_xml_depth; each array holding the values its
// count says and each accessor reading within its array (assimp read past a
// short one, a different model each run); nodes with the nodes they instance
// in no cycle and at most max_nesting_depth deep (assimp recursed until it
// crashed). Throws InputError naming `file`, the byte and the element.
void check_collada_file(std::string_view bytes, const std::string& file);

}  // namespace boxlod
