#include "toolkit/lod/parameter_file.h"

#include "base/input_error.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace boxlod;

TEST(Parameters, SaveThenLoadGivesTheSameValuesExactly) {
    LodParameters p;
    p.model = "/srv/models/house.glb";
    p.level_mode = LevelMode::box_diagonal;
    p.wanted_levels = 7;
    p.current_level = 3;
    p.box_kind = BoxKind::minimal;
    p.interpolation = Interpolation::rank;
    p.keep_small_subtrees = true;
    p.keep_cheaper_subtrees = false;
    p.fovy = 37.123456f;
    p.distance = 1.0f / 3.0f;
    p.resolution = 720;
    p.min_texture_size = 128;
    p.max_texture_size = 2048;
    p.render_mode = RenderMode::pom;
    p.parallax_scale = 0.0123f;
    p.parallax_bias = -0.00617f;
    Camera camera;
    camera.position = {0.1f, 2e-7f, -3.3f};
    camera.target = {1, 2, 3};
    camera.fovy_degrees = 51.5f;
    p.camera = camera;
    Light light;
    light.position = {-7, 8.25f, 1e6f};
    light.shininess = 12;
    p.light = light;

    auto folder = test::scratch_folder("parameters");
    std::string path = (folder / "p.params.txt").string();
    save_parameters(path, p);
    LodParameters q = load_parameters(path);
    EXPECT_EQ(format_parameters(q), format_parameters(p));
    EXPECT_EQ(q.fovy, p.fovy);
    EXPECT_EQ(q.distance, p.distance);
    EXPECT_EQ(q.camera->position, p.camera->position);
    EXPECT_EQ(q.light->position, p.light->position);
}

// An absolute model path is kept as given (no run of "../" spelling out the
// folders between); a relative one, given from the working folder, is
// written relative to the file and reads back to the same model from anywhere.
TEST(Parameters, TheModelIsNamedAsGivenOrRelativeToTheFile) {
    namespace fs = std::filesystem;
    auto folder = test::scratch_folder("parameters_model");
    LodParameters p;
    p.model = "/srv/models/house.ifc";
    save_parameters((folder / "out" / "absolute.params.txt").string(), p);
    EXPECT_NE(test::read_text(folder / "out" / "absolute.params.txt").find("model = /srv/models/house.ifc\n"),
              std::string::npos);
    p.model = (folder / "in" / "house.ifc").lexically_relative(fs::current_path()).string();
    ASSERT_TRUE(fs::path(p.model).is_relative());
    save_parameters((folder / "out" / "relative.params.txt").string(), p);
    EXPECT_NE(test::read_text(folder / "out" / "relative.params.txt").find("model = ../in/house.ifc\n"),
              std::string::npos);
    LodParameters back = load_parameters(fs::absolute(folder / "out" / "relative.params.txt").string());
    EXPECT_EQ(fs::weakly_canonical(back.model), fs::weakly_canonical(folder / "in" / "house.ifc"));
    // Read by its absolute path and saved elsewhere, the model stays relative.
    save_parameters((folder / "again" / "deeper" / "p.params.txt").string(), back);
    EXPECT_NE(
        test::read_text(folder / "again" / "deeper" / "p.params.txt").find("model = ../../in/house.ifc\n"),
        std::string::npos);
    // A file named without a folder (the viewer's default) sits in the working folder.
    const fs::path working = fs::current_path();
    fs::current_path(folder / "out");
    p.model = "../in/house.ifc";
    save_parameters("bare.params.txt", p);
    fs::current_path(working);
    EXPECT_NE(test::read_text(folder / "out" / "bare.params.txt").find("model = ../in/house.ifc\n"),
              std::string::npos);
}

TEST(Parameters, DefaultsAndCommentsParse) {
    LodParameters p =
        parse_parameters("# only a comment\n\n  wanted_levels = 3   # trailing comment\n", "p.txt");
    EXPECT_EQ(p.wanted_levels, 3);
    EXPECT_EQ(p.level_mode, LevelMode::top_down);
    EXPECT_FALSE(p.camera);
}

// A file written while baked proxies were off by default left the key out
// where off: it still builds its level; every file written now names it.
TEST(Parameters, AFileWithoutBakedProxiesReadsThemOff) {
    EXPECT_FALSE(parse_parameters("level_mode = hybrid\n", "old.txt").baked_proxies);
    EXPECT_TRUE(parse_parameters("baked_proxies = true\n", "new.txt").baked_proxies);
    EXPECT_TRUE(LodParameters{}.baked_proxies);
    LodParameters defaults;
    defaults.model = "house.glb";
    EXPECT_TRUE(parse_parameters(format_parameters(defaults), "written.txt").baked_proxies);
}

TEST(Parameters, ErrorsNameFileLineAndKey) {
    auto message = [](const std::string& text) {
        try {
            parse_parameters(text, "bad.txt");
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("fovy = 45\nsmoothness = 3\n"), "bad.txt: line 2: smoothness: unknown key");
    EXPECT_EQ(message("fovy = wide\n"), "bad.txt: line 1: fovy: expected a number in [0.1, 179], got 'wide'");
    EXPECT_EQ(message("fovy = 720\n"), "bad.txt: line 1: fovy: expected a number in [0.1, 179], got '720'");
    EXPECT_EQ(message("current_level = 99999\n"),
              "bad.txt: line 1: current_level: expected a number in [0, 10000], got '99999'");
    EXPECT_EQ(message("fovy = 45\nfovy = 50\n"), "bad.txt: line 2: fovy: given twice (first on line 1)");
    EXPECT_EQ(message("camera_position = 1 2 3\ncamera_target = 1 2 3\n"),
              "bad.txt: the camera's position equals its target");
    EXPECT_EQ(message("camera_position = 0 0 5\ncamera_up = 0 0 0\n"),
              "bad.txt: the camera's up direction is zero");
    EXPECT_EQ(message("camera_position = 0 5 0\n"), "bad.txt: the camera's up direction is along its view");
    // Positions within what the command line takes, and whose distances stay finite in float.
    EXPECT_EQ(message("light_position = 3e38 0 0\n"),
              "bad.txt: line 1: light_position: expected a number in [-1000000000, 1000000000], got '3e38'");
    EXPECT_EQ(message("camera_position = 1e30 0 0\ncamera_target = 0 0 0\n"),
              "bad.txt: line 1: camera_position: expected a number in [-1000000000, 1000000000], got '1e30'");
    EXPECT_EQ(message("light_ambient = 1e39\n"),
              "bad.txt: line 1: light_ambient: expected a number in [0, 100], got '1e39'");
    EXPECT_EQ(message("level_mode = sideways\n")
                  .rfind("bad.txt: line 1: level_mode: unknown value 'sideways' (top-down, ", 0),
              0u);
    EXPECT_EQ(message("just words\n"), "bad.txt: line 1: expected 'key = value'");
    EXPECT_EQ(message("camera_position = 1 2\n"),
              "bad.txt: line 1: camera_position: expected three numbers 'x y z', got '1 2'");
    EXPECT_NE(message("max_texture_size = 1000\n").find("a power of two"), std::string::npos);
    EXPECT_EQ(message("wanted_levels = 1000000000\n"),
              "bad.txt: line 1: wanted_levels: expected a number in [1, 64], got '1000000000'");
    EXPECT_THROW(load_parameters("/nonexistent/p.txt"), InputError);
}
