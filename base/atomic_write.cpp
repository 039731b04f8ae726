#include "base/atomic_write.h"

#include "base/folder_removal.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/utf8.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

namespace boxlod {
namespace {

namespace fs = std::filesystem;

// A file being written: unnamed (Linux O_TMPFILE), so that even SIGKILL leaves
// nothing, and linked into place when complete; or, where the file system has
// no unnamed files (or a group already holds many open), a named temporary
// PATH.boxlod-tmpPID that the next run in its folder removes if a kill left it.
struct Temporary {
    int fd = -1;       // the unnamed file, or -1
    std::string name;  // what a writer opens: /proc/self/fd/N, or the named temporary
};

// A file written inside a group, waiting as its temporary for the group's commit.
struct PendingRename {
    Temporary temporary;
    std::string path;
};

// What an interruption must remove: temporaries being written or waiting for
// their group, and the files a group's commit has renamed so far. Guarded by
// `mutex`; the interrupt thread takes it too.
struct PartialOutputs {
    std::mutex mutex;
    std::set<std::string> temporaries;
    std::vector<PendingRename> pending;
    std::vector<std::string> group_files;
    std::set<std::string> staging_folders;  // of OutputFolders not yet committed
    std::vector<fs::path> made_folders;     // by writes inside the open group: gone with it if left empty
    int open_groups = 0;
    int unnamed_pending = 0;  // unnamed files open (written, or waiting for their group)
};
PartialOutputs& partial_outputs() {
    static PartialOutputs outputs;
    return outputs;
}

// Names no user would give a file: what a killed run left is removed by name.
const std::string temporary_suffix = ".boxlod-tmp";
// An OutputFolder's staging folder: a name of its own, so that clearing what a
// killed run left never removes a user's folder that happens to end in .tmpN.
const std::string staging_suffix = ".boxlod-staging";
// A group's commit journal (OutputGroup::commit), one in each folder the group writes to.
const std::string journal_suffix = ".boxlod-commit";
constexpr std::uintmax_t max_journal_bytes = 64 << 20;
constexpr int max_unnamed_pending = 256;  // well below the usual limit of 1024 open files

std::string named_temporary(const std::string& path, const std::string& suffix = temporary_suffix) {
    return path + suffix + std::to_string(::getpid());
}

// Called with the outputs' mutex held.
Temporary new_temporary(const std::string& path, PartialOutputs& outputs) {
    if (outputs.unnamed_pending < max_unnamed_pending) {
        const fs::path folder = fs::path(path).parent_path();
        const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ++outputs.unnamed_pending;  // until place() or discard() closes it
            return {fd, "/proc/self/fd/" + std::to_string(fd)};
        }
    }
    Temporary named{-1, named_temporary(path)};
    outputs.temporaries.insert(named.name);
    return named;
}

// Under a name: an unnamed file is linked under its named temporary (a link
// cannot replace a file), a named one has it already. Mutex held. Returns the
// name; the temporary is used up (a failed link leaves it to discard()).
std::string named(Temporary& temporary, const std::string& path, PartialOutputs& outputs) {
    std::string from = temporary.name;
    if (temporary.fd >= 0) {
        from = named_temporary(path);
        outputs.temporaries.insert(from);
        ::unlink(from.c_str());
        if (::linkat(AT_FDCWD, temporary.name.c_str(), AT_FDCWD, from.c_str(), AT_SYMLINK_FOLLOW) != 0) {
            outputs.temporaries.erase(from);
            throw_input_error(path, "", std::string("cannot write: ") + std::strerror(errno));
        }
        ::close(temporary.fd);
        --outputs.unnamed_pending;
    }
    temporary = {-1, from};
    return from;
}

// Into place at `path`, replacing what was there: named, then renamed, so
// only a kill between the two leaves a temporary. Mutex held.
void place(Temporary& temporary, const std::string& path, PartialOutputs& outputs) {
    const std::string from = named(temporary, path, outputs);
    temporary = {-1, ""};
    std::error_code error;
    fs::rename(from, path, error);
    if (error) {
        std::error_code ignored;  // the rename's error is the cause to name
        fs::remove(from, ignored);
        outputs.temporaries.erase(from);
        throw_input_error(path, "", "cannot write: " + error.message());
    }
    outputs.temporaries.erase(from);
}

// Gone without a trace. Mutex held.
void discard(const Temporary& temporary, PartialOutputs& outputs) {
    if (temporary.name.empty()) return;  // placed already
    if (temporary.fd >= 0) {
        ::close(temporary.fd);
        --outputs.unnamed_pending;
        return;
    }
    std::error_code ignored;
    fs::remove(temporary.name, ignored);
    outputs.temporaries.erase(temporary.name);
}

// "name.png.boxlod-tmp1234" -> 1234 (with `suffix` ".boxlod-tmp"); 0 when the name is not one of ours.
long temporary_owner(const std::string& filename, const std::string& suffix) {
    std::size_t at = filename.rfind(suffix);
    if (at == std::string::npos || at + suffix.size() == filename.size()) return 0;
    std::string digits = filename.substr(at + suffix.size());
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return 0;
    return std::stol(digits);
}

// Whether the entry at `path` that run `owner` left is stale: that run is
// gone, or it is this run (an id used again, as every run in a container may
// be 1) and the entry is none of those this run is writing. The verdict on
// another run is taken once per folder (`verdicts`): a run that ends between
// two looks must not lose its temporaries while its journal stays. Mutex held.
bool stale(long owner, const fs::path& path, const PartialOutputs& outputs, std::map<long, bool>& verdicts) {
    if (owner <= 0) return false;
    if (owner == ::getpid()) {
        std::error_code error;
        const fs::path entry = fs::absolute(path, error).lexically_normal();
        auto ours = [&](const std::string& live) {
            return fs::absolute(live, error).lexically_normal() == entry;
        };
        return std::none_of(outputs.temporaries.begin(), outputs.temporaries.end(), ours) &&
               std::none_of(outputs.staging_folders.begin(), outputs.staging_folders.end(), ours);
    }
    if (!verdicts.count(owner)) verdicts[owner] = ::kill(pid_t(owner), 0) != 0 && errno == ESRCH;
    return verdicts[owner];
}

// Completes the commit a killed run left half done: renames the temporaries
// its journal lists, in the order listed, and removes the journal. The journal
// is read back as input: a line that is not a temporary of that run in this
// folder makes it no journal of ours, and its temporaries go (the old set stays).
void complete_commit(const fs::path& journal, long owner) {
    const std::string suffix = temporary_suffix + std::to_string(owner);
    std::vector<std::string> names;
    std::error_code error;
    if (fs::is_regular_file(fs::symlink_status(journal, error)) &&
        fs::file_size(journal, error) <= max_journal_bytes && !error) {
        std::ifstream in(journal);
        for (std::string name; std::getline(in, name);) {
            const bool ours = name.size() > suffix.size() && name.find('/') == std::string::npos &&
                              name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
            if (!ours) {
                names.clear();
                break;
            }
            names.push_back(name);
        }
    }
    const fs::path folder = journal.parent_path();
    for (const std::string& name : names)  // our temporaries are plain files: no link, no folder is moved
        if (fs::is_regular_file(fs::symlink_status(folder / name, error)))
            fs::rename(folder / name, folder / name.substr(0, name.size() - suffix.size()), error);
    fs::remove(journal, error);
}

// What boxlod runs that no longer exist (killed with SIGKILL) left in the
// folder outputs go to: commits half done are completed, then temporaries removed.
void remove_stale_temporaries(const fs::path& directory) {
    PartialOutputs& outputs = partial_outputs();
    std::lock_guard lock(outputs.mutex);  // no commit of this run is under way
    std::error_code error;
    std::map<long, bool> verdicts;
    std::vector<std::pair<fs::path, long>> journals;
    for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error))
        if (const long owner = temporary_owner(it->path().filename().string(), journal_suffix);
            stale(owner, it->path(), outputs, verdicts))
            journals.emplace_back(it->path(), owner);
    for (const auto& [journal, owner] : journals) complete_commit(journal, owner);
    for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
        std::error_code ignored;
        if (stale(temporary_owner(it->path().filename().string(), temporary_suffix), it->path(), outputs,
                  verdicts))
            fs::remove(it->path(), ignored);  // a file only
    }
}

// A journal at `path` listing `names`, placed whole. Mutex held.
void place_journal(const std::string& path, const std::string& names, PartialOutputs& outputs) {
    Temporary temporary = new_temporary(path, outputs);
    std::ofstream out(temporary.name, std::ios::binary);
    out << names;
    out.close();
    if (!out) {
        discard(temporary, outputs);
        throw_input_error(path, "", "cannot write file");
    }
    place(temporary, path, outputs);
}

// In each folder the group writes to, a journal: empty while the files take
// their temporaries' names (a kill then leaves the old set: nothing to
// complete), then listing them in commit order. Mutex held. `journals`
// gets each as soon as it is placed.
void write_journals(PartialOutputs& outputs, std::vector<std::string>& journals) {
    std::map<fs::path, std::string> listed;  // per folder, one temporary's name a line
    auto folder_of = [](const std::string& path) {
        std::error_code error;
        return fs::absolute(fs::path(path).parent_path(), error).lexically_normal();
    };
    for (const PendingRename& file : outputs.pending) listed[folder_of(file.path)];
    for (const auto& entry : listed) {
        const std::string journal = (entry.first / (journal_suffix + std::to_string(::getpid()))).string();
        place_journal(journal, "", outputs);
        journals.push_back(journal);
    }
    for (PendingRename& file : outputs.pending) {
        const fs::path from = named(file.temporary, file.path, outputs);
        listed[folder_of(file.path)] += from.filename().string() + "\n";
    }
    std::size_t k = 0;
    for (const auto& entry : listed) place_journal(journals[k++], entry.second, outputs);
}

// The folders a group's writes made (absolute), deepest first, each only if left empty.
void remove_empty_folders(std::vector<fs::path> folders) {
    std::sort(folders.begin(), folders.end(), [](const fs::path& a, const fs::path& b) {
        return std::distance(a.begin(), a.end()) > std::distance(b.begin(), b.end());
    });
    for (const fs::path& folder : folders) ::rmdir(folder.c_str());
}

void remove_files(const std::vector<std::string>& files) {
    for (const std::string& file : files) ::unlink(file.c_str());
}

// The staging folders killed runs left beside `folder` (FOLDER.boxlod-stagingPID,
// FOLDER.old.boxlod-stagingPID, FOLDER.trashK.boxlod-stagingPID): those of
// this folder only, nothing else beside it.
void remove_stale_staging_folders(const fs::path& folder) {
    PartialOutputs& outputs = partial_outputs();
    std::lock_guard lock(outputs.mutex);
    std::error_code error;
    std::map<long, bool> verdicts;
    const std::string name = folder.filename().string();
    std::vector<fs::path> stale_folders;  // listed first: renaming them changes the folder being listed
    for (fs::directory_iterator it(folder.parent_path(), error), end; !error && it != end;
         it.increment(error)) {
        const std::string entry = it->path().filename().string();
        const bool of_this = is_trash_of(entry, name, staging_suffix) ||
                             entry.rfind(name + staging_suffix, 0) == 0 ||
                             entry.rfind(name + ".old" + staging_suffix, 0) == 0;
        if (of_this && stale(temporary_owner(entry, staging_suffix), it->path(), outputs, verdicts))
            stale_folders.push_back(it->path());
    }
    for (const fs::path& stale_folder : stale_folders)
        remove_in_background(stale_folder, free_trash_name(folder, staging_suffix));
}

std::string quoted(const fs::path& path) { return std::string("'").append(path.string()).append("'"); }

// Whether `directory` takes new files: the only sure test is to make one.
void check_writable_directory(const fs::path& directory, const std::string& path) {
    fs::path probe = directory / (".boxlod-probe" + std::to_string(::getpid()));
    int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (fd < 0) throw_input_error(path, "", std::string("cannot write here: ") + std::strerror(errno));
    ::close(fd);
    ::unlink(probe.c_str());
}

}  // namespace

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
    const fs::path folder = fs::path(path).parent_path();  // made here, as check_output_file allows
    std::error_code folder_error;
    std::vector<fs::path> missing;  // the folders this write makes
    for (fs::path p = fs::absolute(folder, folder_error).lexically_normal();
         !fs::exists(p, folder_error) && p != p.parent_path(); p = p.parent_path())
        missing.push_back(p);
    if (!folder.empty()) fs::create_directories(folder, folder_error);
    if (folder_error) throw_input_error(path, "", "cannot make its folder: " + folder_error.message());
    PartialOutputs& outputs = partial_outputs();
    Temporary temporary;
    {
        std::lock_guard lock(outputs.mutex);
        if (outputs.open_groups > 0)
            outputs.made_folders.insert(outputs.made_folders.end(), missing.begin(), missing.end());
        temporary = new_temporary(path, outputs);
    }
    try {
        write(temporary.name);
        std::lock_guard lock(outputs.mutex);
        if (outputs.open_groups > 0) {
            // Placed at the group's commit: a kill before it leaves nothing (unnamed) or only temporaries.
            // A path written again keeps its place in the order, with the last content.
            auto earlier = std::find_if(outputs.pending.begin(), outputs.pending.end(),
                                        [&](const PendingRename& p) { return p.path == path; });
            if (earlier == outputs.pending.end()) {
                outputs.pending.push_back({temporary, path});
            } else if (earlier->temporary.name !=
                       temporary.name) {  // the same name: rewritten in place already
                discard(earlier->temporary, outputs);
                earlier->temporary = temporary;
            }
            return;
        }
        place(temporary, path, outputs);
    } catch (...) {
        std::lock_guard lock(outputs.mutex);
        discard(temporary, outputs);
        throw;
    }
}

namespace {

// The folder that takes `path`'s files: `wanted` or, where it does not exist
// yet, its nearest ancestor that does (the rest is made when writing).
void check_folder_or_ancestor(const fs::path& wanted, const std::string& path) {
    std::error_code error;
    const fs::path absolute = fs::absolute(wanted, error).lexically_normal();
    fs::path existing = absolute;
    while (!fs::exists(existing, error) && existing.has_relative_path()) existing = existing.parent_path();
    if (!fs::is_directory(existing, error))
        throw_input_error(path, "",
                          existing != absolute       ? quoted(existing) + " is not a folder"
                          : wanted == fs::path(path) ? "exists and is not a folder"
                                                     : quoted(wanted) + " is not a folder");
    check_writable_directory(existing, path);
    // What a killed run left goes only from the folder the outputs go to, never from one above it.
    if (existing == absolute) remove_stale_temporaries(existing);
}

}  // namespace

void check_output_file(const std::string& path) {
    std::error_code error;
    if (path.empty()) throw_input_error("''", "", "an empty file name where an output file was expected");
    if (fs::is_directory(path, error)) throw_input_error(path, "", "is a directory, not a file to write");
    if (const std::size_t bytes = fs::path(path).filename().string().size(); bytes > max_output_name_bytes)
        throw_input_error(path, "",
                          "a file name of " + std::to_string(bytes) + " bytes, more than the " +
                              std::to_string(max_output_name_bytes) + " an output may have");
    // Names go into glTF's URIs and tileset.json, which JSON holds as UTF-8.
    if (!is_utf8(fs::path(path).filename().string()))
        throw_input_error(path, "", "the file's name is not UTF-8 text");
    fs::path directory = fs::path(path).parent_path();
    check_folder_or_ancestor(directory.empty() ? fs::path(".") : directory, path);
}

void check_output_file(const std::string& path, std::initializer_list<std::string_view> extensions) {
    check_output_file(path);
    const std::string extension = lowercase_extension(path);
    std::string names;
    for (std::string_view wanted : extensions) {
        if (extension == wanted) return;
        names += (names.empty() ? "" : " or ") + std::string(wanted);
    }
    throw_input_error(path, "", "this output is written as " + names + ": name the file so");
}

void check_output_directory(const std::string& path) {
    if (path.empty()) throw_input_error("''", "", "an empty folder name where an output folder was expected");
    check_folder_or_ancestor(path, path);
}

OutputGroup::OutputGroup() {
    PartialOutputs& outputs = partial_outputs();
    std::lock_guard lock(outputs.mutex);
    ++outputs.open_groups;
    first_pending_ = outputs.pending.size();
}

void OutputGroup::commit() {
    PartialOutputs& outputs = partial_outputs();
    std::lock_guard lock(outputs.mutex);
    if (outputs.open_groups > 1) {  // an inner group: the outermost decides
        committed_ = true;
        return;
    }
    // Renamed in the order written, so the file naming the others (a .gltf) comes
    // last; the interrupt thread cannot run between two renames (it needs the
    // mutex). A kill during the renames leaves the journals, and the next run
    // writing to the folder completes the set (remove_stale_temporaries).
    std::vector<std::string> journals;
    std::size_t placed = 0;
    try {
        if (outputs.pending.size() > 1) write_journals(outputs, journals);
        for (; placed < outputs.pending.size(); ++placed) {
            PendingRename& file = outputs.pending[placed];
            std::error_code error;
            // Take back only the files this group made: one it replaced (a texture
            // shared with a level written before) may be needed by others.
            bool made = !fs::exists(file.path, error);
            place(file.temporary, file.path, outputs);
            if (made) outputs.group_files.push_back(file.path);
        }
    } catch (...) {  // the destructor discards the rest and takes back what was placed
        remove_files(journals);
        outputs.pending.erase(outputs.pending.begin(), outputs.pending.begin() + std::ptrdiff_t(placed));
        throw;
    }
    remove_files(journals);
    outputs.pending.clear();
    outputs.group_files.clear();
    outputs.made_folders.clear();
    committed_ = true;
}

OutputGroup::~OutputGroup() {
    PartialOutputs& outputs = partial_outputs();
    std::lock_guard lock(outputs.mutex);
    if (!committed_) {
        for (std::size_t i = first_pending_; i < outputs.pending.size(); ++i)
            discard(outputs.pending[i].temporary, outputs);
        outputs.pending.resize(std::min(first_pending_, outputs.pending.size()));
        for (const std::string& file : outputs.group_files) {  // a commit that failed half way
            std::error_code ignored;
            fs::remove(file, ignored);
        }
        outputs.group_files.clear();
    }
    if (outputs.open_groups == 1 && !committed_) remove_empty_folders(outputs.made_folders);
    if (outputs.open_groups == 1) outputs.made_folders.clear();
    --outputs.open_groups;
}

namespace {

// Whether `folder` may be swapped for a new one: a real folder (no link, no
// mount point), not the working folder or one above it, holding only what the
// command writes.
bool replaceable(const fs::path& folder, const std::function<bool(const std::string&)>& ours) {
    std::error_code error;
    if (fs::is_symlink(folder, error)) return false;
    if (!fs::exists(folder, error)) return true;
    if (!fs::is_directory(folder, error)) return false;
    const fs::path here = fs::current_path(error);
    for (fs::path p = here; !error && !p.empty(); p = p.parent_path()) {
        if (fs::equivalent(p, folder, error)) return false;
        if (p == p.parent_path()) break;
    }
    struct stat own {
    }, parent{};
    if (::stat(folder.c_str(), &own) != 0 || ::stat(folder.parent_path().c_str(), &parent) != 0 ||
        own.st_dev != parent.st_dev)
        return false;
    for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
        if (!ours(fs::relative(it->path(), folder, error).string())) return false;
    return !error;
}

}  // namespace

OutputFolder::OutputFolder(const std::string& folder, const std::function<bool(const std::string&)>& ours) {
    std::error_code error;
    fs::path absolute = fs::absolute(folder, error).lexically_normal();
    if (!absolute.has_filename()) absolute = absolute.parent_path();  // "out/" names "out"
    folder_ = path_ = absolute.string();
    if (absolute.parent_path() == absolute || !replaceable(absolute, ours)) {
        fs::create_directories(absolute, error);
        if (error) throw_input_error(folder, "", "cannot make this folder: " + error.message());
        return;
    }
    fs::create_directories(absolute.parent_path(), error);
    remove_stale_staging_folders(absolute);
    path_ = named_temporary(folder_, staging_suffix);
    {
        PartialOutputs& outputs = partial_outputs();
        std::lock_guard lock(outputs.mutex);
        outputs.staging_folders.insert(path_);
    }
    fs::remove_all(path_, error);
    fs::create_directory(path_, error);
    if (error) throw_input_error(folder, "", "cannot make its staging folder: " + error.message());
}

void OutputFolder::commit() {
    if (!replaces()) {
        committed_ = true;
        return;
    }
    PartialOutputs& outputs = partial_outputs();
    std::lock_guard lock(
        outputs.mutex);  // no interruption between the swap and forgetting the staging folder
    std::error_code error;
    if (!fs::exists(folder_, error)) {
        fs::rename(path_, folder_, error);
    } else if (::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, folder_.c_str(), RENAME_EXCHANGE) == 0) {
        fs::remove_all(path_, error);  // the old content, now under the staging name
        error.clear();                 // what is left of it goes at the next run
    } else {
        // No exchange on this file system: the old folder moves aside, then the
        // new one in; a kill between the two leaves the folder absent, not mixed.
        const std::string old = named_temporary(folder_ + ".old", staging_suffix);
        fs::rename(folder_, old, error);
        if (!error) fs::rename(path_, folder_, error);
        if (!error) fs::remove_all(old, error);
    }
    if (error) throw_input_error(folder_, "", "cannot put the new folder in place: " + error.message());
    outputs.staging_folders.erase(path_);
    committed_ = true;
}

OutputFolder::~OutputFolder() {
    if (committed_ || !replaces()) return;
    PartialOutputs& outputs = partial_outputs();
    std::lock_guard lock(outputs.mutex);
    std::error_code ignored;
    fs::remove_all(path_, ignored);
    outputs.staging_folders.erase(path_);
}

void write_file_atomically(const std::string& path, std::span<const std::uint8_t> bytes) {
    write_atomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        out.close();
        if (!out) throw_input_error(path, "", "cannot write file");
    });
}

void write_text_atomically(const std::string& path, const std::string& text) {
    write_file_atomically(path, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

void remove_partial_outputs_on_interrupt() {
    // Blocked here, so in every thread started later: only the thread below
    // receives them, with sigwait, where taking a mutex and removing files is safe.
    static sigset_t signals;
    sigemptyset(&signals);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals, s);
    if (pthread_sigmask(SIG_BLOCK, &signals, nullptr) != 0) return;
    std::thread([] {
        int signal = 0;
        if (sigwait(&signals, &signal) != 0) return;
        PartialOutputs& outputs = partial_outputs();
        outputs.mutex.lock();  // held until the end: no file is renamed after this
        for (const std::string& file : outputs.temporaries) ::unlink(file.c_str());
        for (const std::string& file : outputs.group_files) ::unlink(file.c_str());
        remove_empty_folders(outputs.made_folders);
        // Within a second: what is left of a staging folder then goes with the next run
        // (remove_stale_staging_folders).
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
        bool left = false;
        for (const std::string& folder : outputs.staging_folders)
            left = !remove_until(folder, deadline) || left;
        std::fprintf(stderr, "boxlod: interrupted (signal %d); partial outputs removed%s\n", signal,
                     left ? " (a staging folder's rest goes with the next run that writes there)" : "");
        std::_Exit(128 + signal);
    }).detach();
}

}  // namespace boxlod
