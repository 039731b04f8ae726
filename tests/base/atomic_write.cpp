#include "base/atomic_write.h"

#include "base/input_error.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

using namespace boxlod;
namespace fs = std::filesystem;

namespace {
std::string output_problem(void (*check)(const std::string&), const std::string& path) {
    return test::input_error_of([&] { check(path); });
}
}  // namespace

TEST(AtomicWrite, OutputPathsAreCheckedBeforeAnyWork) {
    fs::path folder = test::scratch_folder("atomic_write_paths");
    test::write_text(folder / "file", "x");
    EXPECT_EQ(output_problem(check_output_file, (folder / "a.png").string()), "");
    EXPECT_EQ(output_problem(check_output_file, folder.string()),
              folder.string() + ": is a directory, not a file to write");
    EXPECT_EQ(
        output_problem(check_output_file, (folder / "file" / "a.png").string()),
        (folder / "file" / "a.png").string() + ": '" + (folder / "file").string() + "' is not a folder");
    EXPECT_EQ(output_problem(check_output_file, (folder / "none" / "a.png").string()),
              "");                              // made when written
    EXPECT_FALSE(fs::exists(folder / "none"));  // checked, not made
    EXPECT_EQ(output_problem(check_output_file, "/proc/a.png").rfind("/proc/a.png: cannot write here: ", 0),
              0u);
    // A name goes into glTF's URIs, which JSON holds as UTF-8; a folder's does not.
    EXPECT_EQ(output_problem(check_output_file, (folder / "caf\xe9.gltf").string()),
              (folder / "caf\xe9.gltf").string() + ": the file's name is not UTF-8 text");
    EXPECT_EQ(output_problem(check_output_file, (folder / "caf\xc3\xa9.gltf").string()), "");
    EXPECT_EQ(output_problem(check_output_directory, (folder / "new" / "deeper").string()), "");
    EXPECT_FALSE(fs::exists(folder / "new"));  // checked, not made
    EXPECT_EQ(output_problem(check_output_directory, (folder / "file").string()),
              (folder / "file").string() + ": exists and is not a folder");
    EXPECT_EQ(output_problem(check_output_directory, (folder / "file" / "sub").string()),
              (folder / "file" / "sub").string() + ": '" + (folder / "file").string() + "' is not a folder");
}

// A folder that appears where an output goes, after the check (a level of
// --all-levels named like a folder): the rename's cause is named, not the
// removal's (it said "cannot write: Success").
TEST(AtomicWrite, AFolderInTheWayIsNamedAsTheCause) {
    fs::path folder = test::scratch_folder("atomic_write_folder_in_the_way");
    fs::create_directories(folder / "level.gltf" / "inside");
    const std::string problem =
        test::input_error_of([&] { write_text_atomically((folder / "level.gltf").string(), "x"); });
    EXPECT_EQ(problem, (folder / "level.gltf").string() + ": cannot write: Is a directory");
    EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()),
              1);  // no temporary left
}

TEST(AtomicWrite, AnOutputIsNamedForTheFormatItHolds) {
    fs::path folder = test::scratch_folder("atomic_write_extensions");
    auto problem = [&](const std::string& name) {
        return test::input_error_of([&] { check_output_file((folder / name).string(), {".gltf", ".glb"}); });
    };
    EXPECT_EQ(problem("a.glb"), "");
    EXPECT_EQ(problem("a.GLTF"), "");  // case aside
    EXPECT_EQ(problem("a.obj"),
              (folder / "a.obj").string() + ": this output is written as .gltf or .glb: name the file so");
    EXPECT_NE(problem("glb"), "");  // no extension at all
    EXPECT_EQ(test::input_error_of([&] { check_output_file(folder.string(), {".png"}); }),
              folder.string() + ": is a directory, not a file to write");  // the path is checked first
}

TEST(AtomicWrite, AFileInAFolderThatDoesNotExistYetMakesItsFolder) {
    fs::path folder = test::scratch_folder("atomic_write_folder");
    write_text_atomically((folder / "new" / "deeper" / "a.txt").string(), "made");
    EXPECT_EQ(test::read_text(folder / "new" / "deeper" / "a.txt"), "made");
    test::write_text(folder / "file", "x");
    EXPECT_EQ(test::input_error_of([&] {
                  write_text_atomically((folder / "file" / "a.txt").string(), "no");
              }).rfind((folder / "file" / "a.txt").string() + ": cannot make its folder: ", 0),
              0u);
}

TEST(AtomicWrite, ChecksRemoveTemporariesOfRunsThatNoLongerExist) {
    fs::path folder = test::scratch_folder("atomic_write_stale");
    test::write_text(folder / "a.png.boxlod-tmp999999999", "killed run");  // no process has this id
    test::write_text(folder / ("b.png.boxlod-tmp" + std::to_string(::getpid())),
                     "a run with this run's id, before it");
    test::write_text(folder / "c.tmpfile", "not ours");
    test::write_text(folder / "report.tmp999999999", "a user's, named like a temporary of other programs");
    check_output_file((folder / "a.png").string());
    EXPECT_FALSE(fs::exists(folder / "a.png.boxlod-tmp999999999"));
    EXPECT_FALSE(
        fs::exists(folder / ("b.png.boxlod-tmp" + std::to_string(::getpid()))));  // not one this run writes
    EXPECT_TRUE(fs::exists(folder / "c.tmpfile"));
    EXPECT_TRUE(fs::exists(folder / "report.tmp999999999"));
}

// Only the folder the outputs go to is cleaned: an output folder not made
// yet leaves the folder above it as it is (a user's files there, a journal,
// a folder that looks like a staging folder of another output).
TEST(AtomicWrite, NothingAboveTheOutputFolderIsTouched) {
    fs::path parent = test::scratch_folder("atomic_write_parent");
    test::write_text(parent / "notes.txt.boxlod-tmp999999999", "precious");
    test::write_text(parent / ".boxlod-commit999999999", "notes.txt.boxlod-tmp999999999\n");
    fs::create_directories(parent / "userdir.boxlod-staging999999999");
    test::write_text(parent / "userdir.boxlod-staging999999999" / "data", "precious");
    check_output_directory((parent / "out").string());
    check_output_file((parent / "new" / "a.png").string());
    {
        OutputFolder folder((parent / "tiles").string(), [](const std::string&) { return true; });
    }
    EXPECT_TRUE(fs::exists(parent / "notes.txt.boxlod-tmp999999999"));
    EXPECT_FALSE(fs::exists(parent / "notes.txt"));
    EXPECT_TRUE(fs::exists(parent / ".boxlod-commit999999999"));
    EXPECT_TRUE(fs::exists(parent / "userdir.boxlod-staging999999999" / "data"));
}

TEST(AtomicWrite, AGroupsFilesWaitAsTemporariesUntilTheCommitRenamesThemAll) {
    fs::path folder = test::scratch_folder("atomic_write_commit");
    {
        OutputGroup group;
        write_text_atomically((folder / "a.png").string(), "page");
        write_text_atomically((folder / "b.gltf").string(), "names a.png");
        // A kill now, even one nothing can catch, leaves nothing: the files wait unnamed.
        EXPECT_TRUE(fs::is_empty(folder));
        group.commit();
    }
    EXPECT_EQ(test::read_text(folder / "a.png"), "page");
    EXPECT_EQ(test::read_text(folder / "b.gltf"), "names a.png");
    {  // a file written twice in one group: its last content
        OutputGroup group;
        write_text_atomically((folder / "a.png").string(), "first");
        write_text_atomically((folder / "b.gltf").string(), "names a.png again");
        write_text_atomically((folder / "a.png").string(), "second");
        group.commit();
    }
    EXPECT_EQ(test::read_text(folder / "a.png"), "second");
    for (const auto& entry : fs::directory_iterator(folder))
        EXPECT_EQ(entry.path().filename().string().find(".boxlod-tmp"), std::string::npos);
}

TEST(AtomicWrite, ManyFilesInAGroupWaitAsNamedTemporariesBeyondTheOpenFileBudget) {
    fs::path folder = test::scratch_folder("atomic_write_many");
    {
        OutputGroup group;
        for (int i = 0; i < 300; ++i)
            write_text_atomically((folder / (std::to_string(i) + ".txt")).string(), std::to_string(i));
        std::size_t named = 0;
        for (const auto& entry : fs::directory_iterator(folder))
            named += entry.path().string().find(".boxlod-tmp") != std::string::npos;
        EXPECT_EQ(named, 300u - 256u);                       // the first 256 unnamed, the rest named
        check_output_file((folder / "other.txt").string());  // this run's own temporaries are not leftovers
        std::size_t still = 0;
        for (const auto& entry : fs::directory_iterator(folder))
            still += entry.path().string().find(".boxlod-tmp") != std::string::npos;
        EXPECT_EQ(still, named);
        group.commit();
    }
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        ++files;
        EXPECT_EQ(entry.path().string().find(".boxlod-tmp"), std::string::npos);
    }
    EXPECT_EQ(files, 300u);
    EXPECT_EQ(test::read_text(folder / "299.txt"), "299");
}

TEST(AtomicWrite, AGroupLeftWithoutCommitRemovesTheFilesItMadeButNotThoseItReplaced) {
    fs::path folder = test::scratch_folder("atomic_write_group");
    write_text_atomically((folder / "shared.png").string(), "old");
    try {
        OutputGroup group;
        write_text_atomically((folder / "level.gltf").string(), "new");
        write_text_atomically((folder / "shared.png").string(), "same");
        throw std::runtime_error("the next file cannot be written");
    } catch (const std::runtime_error&) {
    }
    EXPECT_FALSE(fs::exists(folder / "level.gltf"));
    EXPECT_TRUE(fs::exists(folder / "shared.png"));
    try {  // the folders its writes made go with it
        OutputGroup group;
        write_text_atomically((folder / "made" / "deeper" / "a.txt").string(), "x");
        throw std::runtime_error("the next file cannot be written");
    } catch (const std::runtime_error&) {
    }
    EXPECT_FALSE(fs::exists(folder / "made"));
    {
        OutputGroup outer;
        {
            OutputGroup inner;
            write_text_atomically((folder / "inner.bin").string(), "x");
            inner.commit();
        }
        write_text_atomically((folder / "outer.txt").string(), "y");
        // outer is not committed: the outermost group decides for both
    }
    EXPECT_FALSE(fs::exists(folder / "inner.bin"));
    EXPECT_FALSE(fs::exists(folder / "outer.txt"));
    {
        OutputGroup group;
        write_text_atomically((folder / "kept.txt").string(), "z");
        group.commit();
    }
    EXPECT_TRUE(fs::exists(folder / "kept.txt"));
    for (const auto& entry : fs::directory_iterator(folder))
        EXPECT_EQ(entry.path().string().find(".boxlod-tmp"), std::string::npos) << entry.path();
}

// What a SIGKILL during a commit's renames leaves: some files of the new set
// in place, the rest waiting as temporaries, and the journal listing them.
// The next run writing to the folder completes the set; a temporary the
// journal does not list (a file still being written) goes.
TEST(AtomicWrite, TheNextRunCompletesACommitThatAKillCutShort) {
    fs::path folder = test::scratch_folder("atomic_write_journal");
    const std::string dead = ".boxlod-tmp999999999";  // no process has this id
    test::write_text(folder / "a.png", "new");        // renamed before the kill
    test::write_text(folder / ("b.gltf" + dead), "new");
    test::write_text(folder / "b.gltf", "old");
    test::write_text(folder / ("c.png" + dead), "being written");
    test::write_text(folder / ".boxlod-commit999999999", "a.png" + dead + "\nb.gltf" + dead + "\n");
    check_output_file((folder / "other.png").string());
    EXPECT_EQ(test::read_text(folder / "a.png"), "new");
    EXPECT_EQ(test::read_text(folder / "b.gltf"), "new");
    EXPECT_FALSE(fs::exists(folder / "c.png"));
    for (const auto& entry : fs::directory_iterator(folder))
        EXPECT_TRUE(entry.path().filename() == "a.png" || entry.path().filename() == "b.gltf")
            << entry.path();
}

// The journal is read back as input: one that lists anything but the dead
// run's temporaries in its folder is not ours, and the old set stays.
TEST(AtomicWrite, AJournalListingOtherFilesRollsBack) {
    fs::path folder = test::scratch_folder("atomic_write_bad_journal");
    const std::string dead = ".boxlod-tmp999999999";
    test::write_text(folder / "b.gltf", "old");
    test::write_text(folder / ("b.gltf" + dead), "new");
    for (const std::string& line :
         {"../b.gltf" + dead, std::string("b.gltf.boxlod-tmp12"), std::string("b.gltf")}) {
        test::write_text(folder / ("b.gltf" + dead), "new");
        test::write_text(folder / ".boxlod-commit999999999", "b.gltf" + dead + "\n" + line + "\n");
        check_output_file((folder / "other.png").string());
        EXPECT_EQ(test::read_text(folder / "b.gltf"), "old") << line;
        EXPECT_FALSE(fs::exists(folder / ("b.gltf" + dead))) << line;
        EXPECT_FALSE(fs::exists(folder / ".boxlod-commit999999999")) << line;
    }
    // Only plain files are renamed: a listed folder or link stays where it is.
    fs::create_directories(folder / ("sub" + dead));
    fs::create_symlink("/etc/hostname", folder / ("link" + dead));
    test::write_text(folder / ".boxlod-commit999999999", "sub" + dead + "\nlink" + dead + "\n");
    check_output_file((folder / "other.png").string());
    EXPECT_FALSE(fs::exists(folder / "sub"));
    EXPECT_FALSE(fs::is_symlink(folder / "link"));
}

// Real SIGKILLs at moments spread over a run that writes 300 files (more than
// wait unnamed) replacing an old set: half while it writes, half from the
// moment its journal lists them to past the end of its renames. After the next
// run's check the folder holds the old set or the new one, whole, and nothing else.
TEST(AtomicWrite, ASetKilledAtAnyMomentIsOldOrNewAfterTheNextRun) {
    // Its own folder: the sanitized build of these tests may run at the same time.
    fs::path folder = test::scratch_folder("atomic_write_killed" + std::to_string(::getpid()));
    constexpr int files = 300, kills = 12;
    using Clock = std::chrono::steady_clock;
    auto write_set = [&](const std::string& content) {
        OutputGroup group;
        for (int i = 0; i < files; ++i)
            write_text_atomically((folder / (std::to_string(i) + ".txt")).string(), content);
        group.commit();
    };
    // Whether the journal lists the files (it is empty while they take their names).
    auto listing = [](const fs::path& journal) {
        std::error_code error;
        return fs::file_size(journal, error) > 0 && !error;
    };
    // Runs a child writing the new set; kills it `delay` seconds after the start,
    // or after its journal lists the files; returns when that happened and when it ended (seconds from the
    // start).
    auto run_new_set = [&](std::optional<double> delay, bool after_journal) {
        const auto start = Clock::now();
        const pid_t child = ::fork();
        if (child == 0) {
            write_set("new");
            std::_Exit(0);
        }
        const fs::path journal = folder / (".boxlod-commit" + std::to_string(child));
        auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
        double journal_at = -1;
        if (after_journal)
            while (::waitpid(child, nullptr, WNOHANG) == 0 && !listing(journal) && seconds() < 30)
                ::usleep(50);
        if (after_journal) journal_at = seconds();
        if (delay) {
            ::usleep(useconds_t(*delay * 1e6));
            ::kill(child, SIGKILL);
        }
        ::waitpid(child, nullptr, 0);
        return std::pair{journal_at, seconds()};
    };
    write_set("old");
    const auto [journal_at, end_at] =
        run_new_set(std::nullopt, true);  // unhurried: when the renames start and end
    int outcomes[2] = {0, 0};
    for (int k = 0; k < kills; ++k) {
        write_set("old");
        const double share = double(k % (kills / 2)) / (kills / 2);
        if (k < kills / 2)
            run_new_set(journal_at * share, false);
        else
            run_new_set((end_at - journal_at) * 1.2 * share, true);
        check_output_file((folder / "other.txt").string());
        const std::string first = test::read_text(folder / "0.txt");
        std::size_t entries = 0;
        for (const auto& entry : fs::directory_iterator(folder)) {
            ++entries;
            EXPECT_EQ(test::read_text(entry.path()), first) << entry.path() << " after kill " << k;
        }
        EXPECT_EQ(entries, std::size_t(files));
        ++outcomes[first == "new"];
    }
    EXPECT_GT(outcomes[0], 0);  // killed at once: the old set
    EXPECT_GE(outcomes[1],
              kills / 2);  // after the journal listed the files: the next run completed the new set
    fs::remove_all(folder);
}

namespace {
bool tileset_file(const std::string& name) { return name == "tileset.json" || name.rfind("tile_", 0) == 0; }

std::vector<std::string> names_in(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}
}  // namespace

// A folder that holds only what the command writes is replaced whole: the
// new content replaces the old in one rename, and nothing of the old set
// (a tile the new set no longer has) stays beside the new one.
TEST(OutputFolder, AFolderOfOurFilesIsReplacedWholeInOneStep) {
    fs::path parent = test::scratch_folder("output_folder_swap"), folder = parent / "tiles";
    fs::create_directories(folder);
    for (const char* name : {"tileset.json", "tile_1", "tile_2"}) test::write_text(folder / name, "old");
    {
        OutputFolder output(folder.string(), tileset_file);
        EXPECT_TRUE(output.replaces());
        write_text_atomically((fs::path(output.path()) / "tile_1").string(), "new");
        write_text_atomically((fs::path(output.path()) / "tileset.json").string(), "new");
        EXPECT_EQ(test::read_text(folder / "tile_1"), "old");  // not yet: the old set until the commit
        output.commit();
    }
    EXPECT_EQ(names_in(folder), (std::vector<std::string>{"tile_1", "tileset.json"}));
    EXPECT_EQ(test::read_text(folder / "tile_1"), "new");
    EXPECT_EQ(names_in(parent), std::vector<std::string>{"tiles"});  // no staging folder, no old content
}

TEST(OutputFolder, WithoutCommitTheOldFolderStaysAndTheStagingFolderGoes) {
    fs::path parent = test::scratch_folder("output_folder_failed"), folder = parent / "tiles";
    fs::create_directories(folder);
    test::write_text(folder / "tileset.json", "old");
    try {
        OutputFolder output(folder.string(), tileset_file);
        write_text_atomically((fs::path(output.path()) / "tileset.json").string(), "new");
        throw std::runtime_error("a tile cannot be written");
    } catch (const std::runtime_error&) {
    }
    EXPECT_EQ(test::read_text(folder / "tileset.json"), "old");
    EXPECT_EQ(names_in(parent), std::vector<std::string>{"tiles"});
    {
        OutputFolder output((parent / "fresh").string(), tileset_file);  // a folder that does not exist yet
        write_text_atomically((fs::path(output.path()) / "tileset.json").string(), "new");
        EXPECT_FALSE(fs::exists(parent / "fresh"));
        output.commit();
    }
    EXPECT_EQ(test::read_text(parent / "fresh" / "tileset.json"), "new");
}

// A user's folder that holds anything else is never swapped away: the files
// go straight into it and the others stay.
TEST(OutputFolder, AFolderHoldingOtherFilesIsWrittenInPlaceAndKeepsThem) {
    fs::path folder = test::scratch_folder("output_folder_shared");
    test::write_text(folder / "notes.txt", "the user's");
    test::write_text(folder / "tileset.json", "old");
    {
        OutputFolder output(folder.string(), tileset_file);
        EXPECT_FALSE(output.replaces());
        EXPECT_EQ(fs::path(output.path()), fs::absolute(folder).lexically_normal());
        write_text_atomically((fs::path(output.path()) / "tileset.json").string(), "new");
        output.commit();
    }
    EXPECT_EQ(test::read_text(folder / "notes.txt"), "the user's");
    EXPECT_EQ(test::read_text(folder / "tileset.json"), "new");
}

// What a SIGKILL leaves, the staging folder of a process that no longer
// exists, goes when the next run writes beside it; a live run's stays, and so
// does a user's folder that merely ends like a temporary file.
TEST(OutputFolder, StagingFoldersOfKilledRunsGoAtTheNextRun) {
    fs::path parent = test::scratch_folder("output_folder_stale");
    const std::string live = "other.boxlod-staging" + std::to_string(::getpid());
    for (const std::string& name :
         {std::string("tiles.boxlod-staging999999999"), live, std::string("data.tmp999999999")}) {
        fs::create_directories(parent / name);
        test::write_text(parent / name / "tile_1", "content");
    }
    OutputFolder output((parent / "tiles").string(), tileset_file);
    EXPECT_FALSE(fs::exists(parent / "tiles.boxlod-staging999999999"));
    EXPECT_TRUE(fs::exists(parent / live));
    EXPECT_TRUE(fs::exists(parent / "data.tmp999999999" / "tile_1"));
}
