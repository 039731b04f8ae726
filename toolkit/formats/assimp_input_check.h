// Checks assimp does not make, run before it reads a file, so that a small
// hostile file cannot make it allocate without bound, loop, or recurse until
// the stack runs out: header counts that cannot fit the file (PLY, OFF), and
// STEP/IFC files as step_file_check.h checks them, and XML (COLLADA, X3D)
// nested deeper than max_nesting_depth.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace boxlod {

// `bytes` is the whole file, `extension` lower case with its dot. Throws
// InputError naming `file` and the place.
void check_assimp_input(std::string_view bytes, const std::string& extension, const std::string& file);

}  // namespace boxlod
