#include "base/folder_removal.h"

#include <csignal>
#include <spawn.h>
#include <string>
#include <unistd.h>

namespace boxlod {

namespace fs = std::filesystem;

bool remove_until(const fs::path& folder, std::chrono::steady_clock::time_point deadline) {
    std::error_code error;
    for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        if (!it->is_directory()) ::unlink(it->path().c_str());
    }
    fs::remove_all(folder, error);
    return !error;
}

void remove_in_background(const fs::path& folder, const fs::path& trash) {
    std::error_code error;
    fs::rename(folder, trash, error);
    std::string path = (error ? folder : trash).string();
    char rm[] = "rm", flags[] = "-rf", end_of_options[] = "--";
    char* argv[] = {rm, flags, end_of_options, path.data(), nullptr};
    posix_spawnattr_t attributes;
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setsigmask(&attributes, &none);  // a caller may block SIGINT and SIGTERM (atomic_write.h)
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
    pid_t child = 0;
    if (posix_spawnp(&child, "rm", nullptr, &attributes, argv, environ) != 0) fs::remove_all(path, error);
    posix_spawnattr_destroy(&attributes);
}

}  // namespace boxlod
