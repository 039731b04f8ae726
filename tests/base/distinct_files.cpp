#include "base/distinct_files.h"

#include "base/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace boxlod;
namespace fs = std::filesystem;

TEST(DistinctFiles, RefusesAnOutputNamingAnInputOrAnEarlierOutput) {
    const fs::path folder = fs::temp_directory_path() / ("boxlod_distinct_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "model.glb") << "x";
    fs::create_symlink(folder / "model.glb", folder / "link.glb");
    const std::string model = (folder / "model.glb").string(), link = (folder / "link.glb").string();
    EXPECT_NO_THROW(check_distinct_files({{"MODEL", model}},
                                         {{"--output", (folder / "out.png").string()}, {"--exr", ""}}));
    try {
        check_distinct_files({{"MODEL", model}}, {{"--output", (folder / "sub/../model.glb").string()}});
        ADD_FAILURE() << "an output over the input was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--output names the same file as MODEL"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(check_distinct_files({{"MODEL", model}}, {{"--heatmap", link}}),
                 InputError);  // a link to it
    EXPECT_THROW(check_distinct_files(
                     {}, {{"--a", (folder / "x.png").string()}, {"--b", (folder / "x.png").string()}}),
                 InputError);
    fs::remove_all(folder);
}
