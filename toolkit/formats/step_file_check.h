// Checks of an ISO 10303-21 (STEP physical) file, such as IFC's, that its
// readers do not make (assimp's, and web-ifc, which reads a file cut short,
// with cyclic placements or a broken instance without a word): the file ends
// with its trailer; every instance `#N = TYPE(attributes);` lies in a DATA
// section, its parentheses balance and its ';' follows them; its references
// form no cycle and nest at most `max_depth` deep, nor do IFC's spatial
// relationships (aggregation, containment, nesting, voids, fillings).
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace boxlod {

// Throws InputError naming `file` and the instance (#N) or byte.
void check_step_file(std::string_view bytes, const std::string& file, int max_depth);

// Where the STEP string opening at text[i] ends: its closing quote ('' is a
// quote inside it), or text.size() if none.
std::size_t step_string_end(std::string_view text, std::size_t i);

}  // namespace boxlod
