#include "data_gen/samples.h"

#include "base/input_error.h"
#include "data_gen/interpreter.h"
#include "golden.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/model/statistics.h"

#include <gtest/gtest.h>

namespace boxlod {

namespace {

std::string statistic(const KeyValues& statistics, const std::string& key) {
    return value_of(statistics, key);
}

struct Pinned {
    const char* sample;
    const char* nodes;
    const char* with_geometry;
    const char* faces;
    const char* width;
    const char* height;
    const char* depth;
};

}  // namespace

TEST(Samples, AllFourAreEmbedded) {
    EXPECT_EQ(sample_names(), "classical, house, manual, office");
    for (const SampleGrammar& sample : sample_grammars()) EXPECT_GT(sample.text.size(), 100u) << sample.name;
    EXPECT_EQ(sample_grammar("house").file, "house.grammar");
}

TEST(Samples, UnknownSampleListsTheKnownOnes) {
    try {
        sample_grammar("castle");
        FAIL();
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "unknown sample grammar 'castle' (samples: classical, house, manual, office)");
    }
}

// Seed 0, the grammars' own lots. `manual` is within a few percent of the
// Cga-LoD manual's example: 11,139 nodes, 3,319 with geometry, 18,909 faces,
// 32 x 41 x 27 m.
TEST(Samples, StatisticsArePinned) {
    const Pinned pinned[] = {
        {"classical", "123", "89", "696", "28.8", "15.7", "21.599998"},
        {"house", "251", "134", "573", "10.400001", "13.35", "8.52"},
        {"manual", "10748", "3380", "19049", "32.3", "40.999996", "27.3"},
        {"office", "3263", "2386", "6526", "20", "66.1", "21.1"},
    };
    for (const Pinned& p : pinned) {
        Model model = generate_building(sample_grammar(p.sample), {});
        EXPECT_NO_THROW(validate_model(model)) << p.sample;
        KeyValues statistics = model_statistics(model);
        EXPECT_EQ(statistic(statistics, "nodes"), p.nodes) << p.sample;
        EXPECT_EQ(statistic(statistics, "nodes_with_geometry"), p.with_geometry) << p.sample;
        EXPECT_EQ(statistic(statistics, "faces_original"), p.faces) << p.sample;
        EXPECT_EQ(statistic(statistics, "mesh_width"), p.width) << p.sample;
        EXPECT_EQ(statistic(statistics, "mesh_height"), p.height) << p.sample;
        EXPECT_EQ(statistic(statistics, "mesh_depth"), p.depth) << p.sample;
    }
}

TEST(Samples, SeedChangesTheBuilding) {
    BuildingOptions options;
    options.seed = 3;
    Model zero = generate_building(sample_grammar("office"), {}),
          three = generate_building(sample_grammar("office"), options);
    EXPECT_NE(zero.nodes.size(), three.nodes.size());  // the number of floors is drawn
}

TEST(Samples, SameGrammarAndSeedGiveIdenticalFiles) {
    auto folder = test::scratch_folder("samples_determinism");
    BuildingOptions options;
    options.seed = 5;
    Grammar grammar = sample_grammar("manual");
    save_model(generate_building(grammar, options), (folder / "a.glb").string());
    save_model(generate_building(sample_grammar("manual"), options), (folder / "b.glb").string());
    std::string a = test::read_text(folder / "a.glb"), b = test::read_text(folder / "b.glb");
    EXPECT_GT(a.size(), 100000u);
    EXPECT_EQ(a, b);
}

TEST(Samples, ExportedScopesAndRulesReadBack) {
    auto folder = test::scratch_folder("samples_read_back");
    Model model = generate_building(sample_grammar("house"), {});
    save_model(model, (folder / "house.gltf").string());
    Model back = load_model((folder / "house.gltf").string());
    ASSERT_EQ(back.nodes.size(), model.nodes.size());
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        EXPECT_EQ(back.nodes[i].rule, model.nodes[i].rule);
        ASSERT_TRUE(back.nodes[i].scope.has_value());
        EXPECT_LT((back.nodes[i].scope->center - model.nodes[i].scope->center).norm(), 1e-5f);
    }
    EXPECT_EQ(back.textures.size(), model.textures.size());
}

}  // namespace boxlod

namespace boxlod {

// A golden render of each sample (and a small city) in normal mode from the
// default view: what the grammars build, pinned pixel for pixel.
TEST(SamplesGolden, EachSampleRendered) {
    for (const SampleGrammar& sample : sample_grammars()) {
        Model model = generate_building(sample_grammar(std::string(sample.name)), {});
        auto drawable = make_drawable_model(model);
        const Bounds& bounds = drawable->drawable.bounds;
        float radius = bounds.size().norm() / 2;
        RenderSettings settings;
        settings.camera =
            camera_at_position({1, 1, 1}, bounds.center(), framing_distance(radius, 45), 45, radius);
        settings.light = light_for_camera(settings.camera);
        Frame frame = make_frame(160, 120, {1, 1, 1});
        render(drawable->drawable.batches, settings, frame);
        test::expect_golden(frame_to_srgb8(frame), "sample_" + std::string(sample.name));
    }
}

}  // namespace boxlod
