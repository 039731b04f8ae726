#include "toolkit/lod/lod_parameters.h"

#include "toolkit/lod/parameter_file.h"

#include <gtest/gtest.h>

#include <set>

using namespace boxlod;

TEST(LodParameters, KeysAndOptionsAreDeclaredOnce) {
    std::set<std::string> keys, options;
    for (const ParameterDeclaration& d : lod_parameter_declarations()) {
        EXPECT_TRUE(keys.insert(d.key).second) << d.key;
        EXPECT_TRUE(options.insert(d.option).second) << d.option;
        EXPECT_FALSE(d.help.empty()) << d.key;
        EXPECT_EQ(find_lod_parameter(d.key), &d);
    }
    EXPECT_EQ(find_lod_parameter("smoothness"), nullptr);
    EXPECT_EQ(keys.size(), 21u);
}

TEST(LodParameters, EveryValueReadsBackAsWritten) {
    LodParameters changed;
    changed.model = "m.glb";
    changed.level_mode = LevelMode::box_volume;
    changed.wanted_levels = 5;
    changed.budgets = {{false, 2e6}, {false, 1024}};
    changed.box_kind = BoxKind::minimal;
    changed.keep_small_subtrees = true;
    changed.crop_faces = false;
    changed.baked_proxies = false;
    changed.fovy = 33.3f;
    changed.resolution = 720.5f;
    changed.max_texture_size = 1024;
    changed.render_mode = RenderMode::pom;
    changed.parallax_bias = -0.0123f;
    changed.level_distances = {LevelDistances::Rule::listed, {12.5f, 40, 1e9f}};
    changed.city_lod = "2.2";
    for (const LodParameters& p : {LodParameters{}, changed})
        for (const ParameterDeclaration& d : lod_parameter_declarations()) {
            LodParameters read;
            ASSERT_EQ(d.parse(d.format(p), read), "") << d.key;
            EXPECT_EQ(d.format(read), d.format(p)) << d.key;
        }
    EXPECT_EQ(parse_parameters(format_parameters(changed), "p.txt").parallax_bias, changed.parallax_bias);
    // A CityJSON model's LoD is written only where one is asked.
    EXPECT_EQ(parse_parameters(format_parameters(changed), "p.txt").city_lod, "2.2");
    EXPECT_EQ(format_parameters(LodParameters{}).find("city_lod"), std::string::npos);
}

TEST(LodParameters, ParsingChecksTheDeclaredRange) {
    LodParameters p;
    EXPECT_EQ(find_lod_parameter("wanted_levels")->parse("65", p), "expected a number in [1, 64], got '65'");
    EXPECT_EQ(find_lod_parameter("wanted_levels")->parse("2.5", p),
              "expected a whole number in [1, 64], got '2.5'");
    EXPECT_EQ(find_lod_parameter("fovy")->parse("nan", p), "expected a number in [0.1, 179], got 'nan'");
    EXPECT_EQ(find_lod_parameter("max_texture_size")->parse("1000", p),
              "expected a power of two in [1, 16384], got '1000'");
    EXPECT_EQ(find_lod_parameter("crop_faces")->parse("yes", p), "expected true or false, got 'yes'");
    EXPECT_EQ(find_lod_parameter("box_kind")->parse("round", p).rfind("unknown value 'round' (", 0), 0u);
    EXPECT_EQ(p.wanted_levels, LodParameters{}.wanted_levels);  // nothing set on failure
    EXPECT_EQ(find_lod_parameter("wanted_levels")->parse("12", p), "");
    EXPECT_EQ(p.wanted_levels, 12);
}

TEST(LodParameters, HelpStatesTheDefaultFromTheStruct) {
    EXPECT_EQ(find_lod_parameter("resolution")->help_text(),
              "texture sizing: screen height in pixels (default 1080)");
    EXPECT_EQ(find_lod_parameter("level_mode")->help_text().find("(default top-down)") != std::string::npos,
              true);
    EXPECT_EQ(find_lod_parameter("keep_small_subtrees")->help_text().find("default"),
              std::string::npos);  // a flag
}

TEST(LodParameters, ValidationChecksEveryDeclaredRange) {
    for (const ParameterDeclaration& d : lod_parameter_declarations()) {
        if (!d.range) continue;
        // Write a value past the range's top through the file format's own text.
        LodParameters p;
        std::string text = format_parameters(p);
        std::string line = d.key + " = " + d.format(p) + "\n";
        ASSERT_NE(text.find(line), std::string::npos) << d.key;
        LodParameters outside = p;
        EXPECT_EQ(d.parse(std::to_string(d.range->max * 2 + 1), outside).empty(), false) << d.key;
    }
    LodParameters p;
    p.wanted_levels = 0;  // set in code, past the declared range
    EXPECT_THROW(validate_parameters(p, "code"), InputError);
    p = LodParameters{};
    p.min_texture_size = 8192;  // above max_texture_size
    EXPECT_THROW(validate_parameters(p, "code"), InputError);
    EXPECT_NO_THROW(validate_parameters(LodParameters{}, "code"));
}
