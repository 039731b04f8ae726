// The file-lods baseline (docs/sweeps.md): a CityJSON model's own coarser
// LoDs, read from the same file, as the official ladder a sweep measures
// boxlod's levels against (3DBAG's LoD 1.3 and 1.2 below 2.2).
#pragma once
#include <string>
#include <vector>

namespace boxlod {

// The LoDs of the model at `path` (FILE or FILE#OBJECT) coarser than the one
// read (`city_lod`, "" for the file's finest), finest first; none for another format.
std::vector<std::string> coarser_file_lods(const std::string& city_lod, const std::string& path);

}  // namespace boxlod
