// Checks assimp does not make, run before it reads a file, so that a small
// hostile file cannot make it allocate without bound, loop, or recurse until
// the stack runs out: header counts that cannot fit the file (PLY, OFF), and
// STEP/IFC files cut short, or whose references form a cycle or nest deeper
// than max_nesting_depth (ISO 10303-21: entity instances `#N = TYPE(...);`), and
// XML (COLLADA, X3D) nested deeper than that.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace boxlod {

// `bytes` is the whole file, `extension` lower case with its dot. Throws
// InputError naming `file` and the place.
void check_assimp_input(std::string_view bytes, const std::string& extension, const std::string& file);

// Where the STEP string opening at text[i] ends: its closing quote ('' is a
// quote inside it), or text.size() if none.
std::size_t step_string_end(std::string_view text, std::size_t i);

// The STEP checks alone, references nested at most `max_depth` deep: also what
// web-ifc needs before it reads an IFC file (ifc_io.h), as it reads a file cut
// short or with cyclic placements without a word (with no depth limit: it
// reads deep chains of boolean cuts, and runs in a child process).
void check_step_file(std::string_view bytes, const std::string& file, int max_depth);

}  // namespace boxlod
