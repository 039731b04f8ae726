#include "base/distinct_files.h"

#include "base/input_error.h"

#include <filesystem>
#include <system_error>

namespace boxlod {

namespace fs = std::filesystem;

void check_distinct_files(const std::vector<std::pair<std::string, std::string>>& inputs,
                          const std::vector<std::pair<std::string, std::string>>& outputs) {
    std::vector<std::pair<std::string, fs::path>> seen;
    auto same_file = [](const std::string& path) {
        std::error_code error;
        fs::path resolved = fs::weakly_canonical(path, error);
        return error ? fs::absolute(path, error).lexically_normal() : resolved;
    };
    for (const auto& [option, path] : inputs)
        if (!path.empty()) seen.emplace_back(option, same_file(path));
    for (const auto& [option, path] : outputs) {
        if (path.empty()) continue;
        const fs::path file = same_file(path);
        for (const auto& [earlier, earlier_file] : seen)
            if (earlier_file == file)
                throw_input_error(path, "", option + " names the same file as " + earlier);
        seen.emplace_back(option, file);
    }
}

}  // namespace boxlod
