#include "base/folder_removal.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <thread>

namespace fs = std::filesystem;
using namespace boxlod;

namespace {

fs::path folder_of_files(const std::string& name, int files) {
    const fs::path folder = test::scratch_folder(name) / "frames";
    fs::create_directories(folder / "inner");
    for (int k = 0; k < files; ++k)
        test::write_text(folder / (k % 2 ? "inner" : ".") / ("frame_" + std::to_string(k)), "x");
    return folder;
}

}  // namespace

// Past its deadline it stops, the folder still there; with time it removes the folder whole.
TEST(FolderRemoval, RemovesUntilItsDeadline) {
    const fs::path folder = folder_of_files("folder_removal_until", 20);
    EXPECT_FALSE(remove_until(folder, std::chrono::steady_clock::now() - std::chrono::seconds(1)));
    EXPECT_TRUE(fs::exists(folder));
    EXPECT_TRUE(remove_until(folder, std::chrono::steady_clock::now() + std::chrono::seconds(60)));
    EXPECT_FALSE(fs::exists(folder));
}

// The folder is gone from its name at once; its trash goes without the caller waiting.
TEST(FolderRemoval, InTheBackgroundTheNameIsFreeAtOnce) {
    const fs::path folder = folder_of_files("folder_removal_background", 200);
    const fs::path trash = folder.parent_path() / "frames.trash";
    remove_in_background(folder, trash);
    EXPECT_FALSE(fs::exists(folder));
    bool gone = false;
    for (int k = 0; k < 200 && !gone; ++k) {
        gone = !fs::exists(trash);
        if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    EXPECT_TRUE(gone);
}

// A trash name in use (a run before with this process id left it): the folder stays as it is.
TEST(FolderRemoval, AFolderThatCannotMoveAsideStays) {
    const fs::path folder = folder_of_files("folder_removal_taken", 4);
    const fs::path trash = folder.parent_path() / "frames.trash";
    fs::create_directories(trash / "kept");
    remove_in_background(folder, trash);
    EXPECT_TRUE(fs::exists(folder / "frame_0"));
    EXPECT_TRUE(fs::exists(trash / "kept"));
}
