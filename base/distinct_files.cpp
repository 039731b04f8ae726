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

void check_input_kept(const std::string& input, const std::string& folder,
                      const std::function<bool(const std::string& name)>& written, const std::string& how) {
    // The file a path leads to (symbolic links resolved), and the name it has in its folder.
    std::error_code file_error, absolute_error, named_error, folder_error;
    const fs::path file = fs::weakly_canonical(input, file_error),
                   absolute = fs::absolute(input, absolute_error);
    const fs::path named =
        absolute_error ? fs::path()
                       : fs::weakly_canonical(absolute.parent_path(), named_error) / absolute.filename();
    const fs::path out = fs::weakly_canonical(folder, folder_error);
    if (folder_error) return;
    auto claimed = [&](const fs::path& f) {
        return f.parent_path() == out && written(f.filename().string());
    };
    if ((!file_error && claimed(file)) || (!absolute_error && !named_error && claimed(named)))
        throw_input_error(input, "", how + " would write over it");
}

}  // namespace boxlod
