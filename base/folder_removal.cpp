#include "base/folder_removal.h"

#include <fcntl.h>
#include <spawn.h>
#include <unistd.h>
#include <csignal>
#include <string>

namespace boxlod {

namespace fs = std::filesystem;

bool remove_until(const fs::path& folder, std::chrono::steady_clock::time_point deadline) {
    std::error_code error;
    for (fs::recursive_directory_iterator it(folder, error), end; it != end; it.increment(error)) {
        if (error || std::chrono::steady_clock::now() > deadline) return false;
        std::error_code status_error;
        if (!fs::is_directory(it->symlink_status(status_error)) && !status_error)
            ::unlink(it->path().c_str());
    }
    if (error) return false;  // not listed: what remains, if anything, is left for later
    fs::remove_all(folder, error);
    return !error;
}

fs::path free_trash_name(const fs::path& folder, const std::string& suffix) {
    std::error_code error;
    for (long k = 0;; ++k)
        if (fs::path trash = folder.parent_path() / (folder.filename().string() + ".trash" +
                                                     std::to_string(k) + suffix + std::to_string(::getpid()));
            !fs::exists(fs::symlink_status(trash, error)))
            return trash;
}

bool is_trash_of(const std::string& entry, const std::string& name, const std::string& suffix) {
    const std::string prefix = name + ".trash";
    if (entry.rfind(prefix, 0) != 0) return false;
    const std::size_t digits = entry.find_first_not_of("0123456789", prefix.size());
    return digits > prefix.size() && digits != std::string::npos &&
           entry.compare(digits, suffix.size(), suffix) == 0;
}

void remove_in_background(const fs::path& folder, const fs::path& trash) {
    std::error_code error;
    fs::rename(folder, trash, error);
    if (error) return;  // left as it is: a later run tries again, and never removes a name in use
    std::string path = trash.string();
    char rm[] = "/bin/rm", flags[] = "-rf", end_of_options[] = "--";
    char* argv[] = {rm, flags, end_of_options, path.data(), nullptr};
    // Detached: a session of its own (no terminal's Ctrl-C), no output on
    // ours, and not blocking the signals this process blocks (atomic_write.h).
    posix_spawnattr_t attributes;
    posix_spawn_file_actions_t files;
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSID);
    posix_spawn_file_actions_init(&files);
    for (int fd : {0, 1, 2})
        posix_spawn_file_actions_addopen(&files, fd, "/dev/null", fd == 0 ? O_RDONLY : O_WRONLY, 0);
    pid_t child = 0;
    if (posix_spawn(&child, rm, &files, &attributes, argv, environ) != 0) fs::remove_all(trash, error);
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
}

}  // namespace boxlod
