// Checks of an ISO 10303-21 (STEP physical) file, such as IFC's, that its
// readers do not make (assimp's, and web-ifc, which reads a file cut short,
// with cyclic placements or a broken instance without a word): the file ends
// with its trailer; every instance `#N = TYPE(attributes);` lies in a DATA
// section, its parentheses balance and its ';' follows them; every entity is
// defined once, numbered within [1, 2^32 - 1] (web-ifc keeps 32 bits), and
// every one an instance names is defined; its references form no cycle and
// nest at most `max_depth` deep, nor do IFC's spatial relationships
// (aggregation, containment, nesting, voids, fillings).
#pragma once
#include <string>
#include <string_view>

namespace boxlod {

// Throws InputError naming `file` and the instance (#N) or byte.
void check_step_file(std::string_view bytes, const std::string& file, int max_depth);

}  // namespace boxlod
