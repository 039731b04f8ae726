// Removing folders of many files without making anyone wait: a long city
// run's staged frames take tens of seconds to remove, which a stop or the
// next run must not wait for (base/atomic_write.h: OutputFolder).
#pragma once
#include <chrono>
#include <filesystem>
#include <string>

namespace boxlod {

// Removes `folder`'s files one by one until `deadline`, then the folder if
// they all went; whether it did (false also where it cannot be listed).
bool remove_until(const std::filesystem::path& folder, std::chrono::steady_clock::time_point deadline);

// Renames `folder` to `trash` at once (beside it; a name nothing has) and
// removes it with a detached `rm -rf` that this process does not wait for
// (its own session, no output; a zombie until this process ends), or here
// and now where it cannot be started. A folder that cannot be renamed is
// left as it is: a later run tries again.
void remove_in_background(const std::filesystem::path& folder, const std::filesystem::path& trash);

// Where a folder goes to be removed: FOLDER.trashK<suffix><pid>, the first K
// that nothing has yet (a run before with this process id may have left one).
std::filesystem::path free_trash_name(const std::filesystem::path& folder, const std::string& suffix);

// Whether `entry` (a file name) is such a name for the folder named `name`.
bool is_trash_of(const std::string& entry, const std::string& name, const std::string& suffix);

}  // namespace boxlod
