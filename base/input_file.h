// Files named by the user, opened with one clear line for each way they can
// be wrong: missing, a directory, unreadable, or too large to be real input.
#pragma once
#include <cstddef>
#include <string>

namespace boxlod {

// The largest input file read whole into memory (models, grammars, configs).
constexpr std::size_t max_input_file_bytes = std::size_t(2) << 30;

// Throws InputError "path: no such file" / "path: is a directory, not a KIND" /
// "path: cannot read ..." unless path is a readable regular file; returns its size.
std::size_t check_input_file(const std::string& path, const std::string& kind);

// The whole file, after check_input_file.
std::string read_input_file(const std::string& path, const std::string& kind);

// A file name's extension in lower case, with its dot (".glb"; "" without one):
// what picks a reader or states an output's format.
std::string lowercase_extension(const std::string& path);

}  // namespace boxlod
