// Files appear whole or not at all: write an unnamed file in the target's
// folder (Linux O_TMPFILE) and link it into place, or where the file system
// has none, a temporary name beside the target, then rename (docs/design.md: Files). Files that belong
// together (one LoD level) appear together or not at all, even when the run is interrupted.
#pragma once
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace boxlod {

// Calls write(temporary_path), then puts it at path (making path's folders).
// If write throws, the temporary file is removed and the exception passes on;
// a failed rename is an InputError naming path. temporary_path is
// /proc/self/fd/N for an unnamed file, which a kill of any kind removes, else
// PATH.boxlod-tmpPID (also, for an instant, between linking and renaming).
void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write);

void write_file_atomically(const std::string& path, std::span<const std::uint8_t> bytes);
void write_text_atomically(const std::string& path, const std::string& text);

// Checked before any work, so a bad output path costs nothing: each throws
// InputError "path: what" unless a file can be created there. Where the
// folder exists, both also complete the commits a killed run of boxlod left
// half done in it, then remove its temporaries; no folder above is touched.
void check_output_file(
    const std::string& path);  // its folder exists and takes new files; path is no folder; its name fits
// The longest file name an output may have: the file system's 255 bytes less its temporary's suffix.
constexpr std::size_t max_output_name_bytes = 255 - 24;
// ... and its name ends in one of `extensions` (".png"; case aside): a file
// named .exr that holds PNG bytes misleads every reader after it.
void check_output_file(const std::string& path, std::initializer_list<std::string_view> extensions);
void check_output_directory(
    const std::string& path);  // a folder that takes new files, or one that can be made

// Files that appear together or not at all: inside a group, atomic writes
// leave their temporaries, and the outermost group's commit() renames them all
// in the order written (so the file naming the others goes last). A group
// destroyed without commit() (an exception passing) removes its files; a kill
// of any kind before the commit leaves nothing (at most 256 unnamed files wait
// at once; later ones wait as named temporaries). The commit first gives
// every file its temporary's name and lists them in a journal,
// FOLDER/.boxlod-commitPID, so a kill during the renames leaves a set that
// the next run writing to the folder completes (check_output_file); a kill
// before the journal lists them leaves the old set. Groups nest, the
// outermost decides.
class OutputGroup {
public:
    OutputGroup();
    ~OutputGroup();
    void commit();  // throws InputError naming a file that cannot be renamed, and removes the others
    OutputGroup(const OutputGroup&) = delete;
    OutputGroup& operator=(const OutputGroup&) = delete;

private:
    std::size_t first_pending_;
    bool committed_ = false;
};

// A folder one command fills whole (a tileset, a city fly-through): written
// as a staging folder beside it, FOLDER.boxlod-stagingPID, and put in place
// with one rename (exchanged with the old folder, which is then removed), so that
// readers, failures and kills of any kind find the old content or the new,
// never a mix (docs/testing.md: Hardening). The old folder is replaced only if
// everything in it is something the command writes (`ours(name)`, for each
// entry's path relative to the folder) and it is neither a symbolic link, a
// mount point, nor the working folder or above it; otherwise the files go
// straight into it, each atomic, and the others stay. A kill leaves the old
// folder whole and the staging folder beside it, which the next run that
// writes there removes.
class OutputFolder {
public:
    OutputFolder(const std::string& folder, const std::function<bool(const std::string& name)>& ours);
    ~OutputFolder();                                    // without commit(): the staging folder is removed
    const std::string& path() const { return path_; }   // where to write the files
    bool replaces() const { return path_ != folder_; }  // written aside and swapped in
    void commit();  // throws InputError naming the folder if it cannot be put in place
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;

private:
    std::string folder_, path_;
    bool committed_ = false;
};

// Call first in main(), before any thread starts: SIGINT, SIGTERM and SIGHUP
// then remove every temporary being written, every file of an open group and
// every staging folder, and end the process with status 128 + the signal.
// (SIGKILL cannot be caught: unnamed files vanish with the process, named
// temporaries and staging folders go at the next run, see check_output_file.)
void remove_partial_outputs_on_interrupt();

}  // namespace boxlod
