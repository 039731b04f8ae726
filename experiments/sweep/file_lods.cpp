#include "experiments/sweep/file_lods.h"

#include "base/input_file.h"
#include "toolkit/formats/cityjson_import.h"

#include <algorithm>
#include <filesystem>

namespace boxlod {

std::vector<std::string> coarser_file_lods(const std::string& city_lod, const std::string& path) {
    std::string file = path;
    std::error_code error;
    if (const std::size_t hash = path.rfind('#');
        hash != std::string::npos && !std::filesystem::exists(path, error))
        file = path.substr(0, hash);
    const std::string extension = lowercase_extension(file);
    if (path.empty() || (extension != ".json" && extension != ".jsonl")) return {};
    const std::vector<std::string> lods = cityjson_lods(file);
    auto read = std::find(lods.begin(), lods.end(), city_lod);
    if (read == lods.end()) read = lods.empty() ? lods.end() : lods.begin();  // the finest, read by default
    return {read == lods.end() ? read : read + 1, lods.end()};
}

}  // namespace boxlod
