#include "toolkit/commands/lod_options.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace boxlod;

namespace {

LodParameters parse(const std::vector<std::string>& words) {
    Command command{"test", "MODEL", "", lod_options(), 1, 1};
    std::vector<std::string> all{"model.glb"};
    all.insert(all.end(), words.begin(), words.end());
    return lod_parameters_from(parse_arguments(command, all));
}

}  // namespace

TEST(LodOptions, OneOptionPerDeclaredParameterWithItsRange) {
    std::vector<Option> options = lod_options();
    ASSERT_EQ(options.size(), lod_parameter_declarations().size() + 2);  // and --params, --manual
    for (const ParameterDeclaration& d : lod_parameter_declarations()) {
        auto o =
            std::find_if(options.begin(), options.end(), [&](const Option& o) { return o.name == d.option; });
        ASSERT_NE(o, options.end()) << d.option;
        EXPECT_EQ(o->help, d.help_text());
        EXPECT_EQ(o->range.has_value(), d.range.has_value());
    }
    EXPECT_EQ(lod_options({"wanted_levels", "level_mode"}).size(), 2u);
    EXPECT_EQ(lod_options({"wanted_levels", "level_mode"})[0].name, "level-mode");  // declaration order
}

TEST(LodOptions, OptionsSetTheirParameters) {
    LodParameters p =
        parse({"--level-mode", "box-volume", "--wanted-levels", "5", "--box", "minimal", "--no-crop",
               "--keep-small-subtrees", "--resolution", "720", "--min-texture-size", "64"});
    EXPECT_EQ(p.model, "model.glb");
    EXPECT_EQ(p.level_mode, LevelMode::box_volume);
    EXPECT_EQ(p.wanted_levels, 5);
    EXPECT_EQ(p.box_kind, BoxKind::minimal);
    EXPECT_FALSE(p.crop_faces);  // a flag sets the opposite of the default
    EXPECT_TRUE(p.keep_small_subtrees);
    EXPECT_TRUE(p.keep_cheaper_subtrees);  // the default: the chain that pays its way
    EXPECT_EQ(p.resolution, 720);
    EXPECT_EQ(p.min_texture_size, 64);
    EXPECT_FALSE(parse({"--box-cheaper-subtrees"}).keep_cheaper_subtrees);
}

TEST(LodOptions, ManualSetsTheManualsProgramAndOptionsChangeSingleParameters) {
    const LodParameters defaults = parse({});
    EXPECT_TRUE(defaults.keep_cheaper_subtrees);
    EXPECT_EQ(defaults.min_texture_size, 16);
    EXPECT_EQ(defaults.flat_faces, 8);
    const LodParameters manual = parse({"--manual"});
    EXPECT_FALSE(manual.keep_cheaper_subtrees);
    EXPECT_EQ(manual.min_texture_size, 256);
    EXPECT_EQ(manual.flat_faces, 0);
    EXPECT_EQ(parse({"--manual", "--flat-faces", "4"}).flat_faces, 4);
}

TEST(LodOptions, ManualAndOptionsWinOverAParameterFile) {
    const std::string file = testing::TempDir() + "lod_options_params.txt";
    std::FILE* out = std::fopen(file.c_str(), "w");
    std::fputs("min_texture_size = 32\nflat_faces = 4\n", out);
    std::fclose(out);
    const LodParameters manual = parse({"--params", file, "--manual"});
    EXPECT_EQ(manual.min_texture_size, 256);  // before, the file's values replaced what --manual set
    EXPECT_EQ(manual.flat_faces, 0);
    EXPECT_EQ(parse({"--params", file, "--manual", "--flat-faces", "2"}).flat_faces, 2);
    EXPECT_EQ(parse({"--params", file}).min_texture_size, 32);
}

TEST(LodOptions, ErrorsNameTheOption) {
    auto message = [](const std::vector<std::string>& words) {
        try {
            parse(words);
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message({"--box", "round"}).rfind("--box: unknown value 'round' (", 0), 0u);
    EXPECT_EQ(message({"--min-texture-size", "100"}),
              "--min-texture-size: expected a power of two in [1, 16384], got '100'");
    EXPECT_NE(message({"--min-texture-size", "8192"}).find("min <= max"), std::string::npos);
}
