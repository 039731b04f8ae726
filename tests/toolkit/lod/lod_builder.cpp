#include "toolkit/lod/lod_builder.h"

#include "base/input_error.h"
#include "golden.h"
#include "lod_scene.h"
#include "test_support.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/lod/cut/error_greedy.h"
#include "toolkit/lod/lod_export.h"
#include "toolkit/model/statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

using namespace boxlod;

namespace {

std::string statistic(const Lod& lod, const std::string& key) { return value_of(lod.statistics, key); }

// The manual's program: the builder's mechanics on a cut that boxes every sub-tree.
LodParameters small_parameters() {
    LodParameters p;
    set_manual(p);
    p.level_mode = LevelMode::top_down;
    p.box_kind = BoxKind::expanded;
    p.resolution = 64;  // small textures keep the tests fast
    p.min_texture_size = 64;
    p.max_texture_size = 512;
    return p;
}

}  // namespace

TEST(LodBuilder, LevelZeroIsTheOriginalAndTheTopLevelOneBox) {
    Model model = test::lod_test_building();
    auto session = start_lod(model, small_parameters(), 2);
    int n = session->derived.levels.obtained_levels;
    EXPECT_EQ(n, 4);  // top-down: depth 3 + 1
    Lod original = build_lod(*session, 0, 2);
    EXPECT_EQ(statistic(original, "faces_lod"), statistic(original, "faces_original"));
    EXPECT_EQ(statistic(original, "faces_lod"), std::to_string(mesh_counts(model).faces));
    EXPECT_EQ(statistic(original, "nodes_with_box"), "0");
    Lod top = build_lod(*session, n, 2);
    EXPECT_EQ(statistic(top, "faces_lod"), "6");  // six quads
    EXPECT_EQ(statistic(top, "triangles_lod"), "12");
    EXPECT_EQ(statistic(top, "used_nodes"), "1");
    EXPECT_EQ(statistic(top, "nodes_with_box"), "1");
    EXPECT_EQ(statistic(top, "lod_textures"), "1");
    EXPECT_THROW(build_lod(*session, n + 1, 2), InputError);
}

// depth_error: the error-greedy proxy of the cut, e(n) summed over its boxes (0 at the original).
TEST(LodBuilder, EveryLevelStatesTheProxyErrorOfItsBoxes) {
    Model model = test::lod_test_building();
    auto session = start_lod(model, small_parameters(), 2);
    const std::vector<double> errors = box_depth_errors(model, session->derived.boxes);
    double coarsest = -1;
    for (int c = 0; c <= session->derived.levels.obtained_levels; ++c) {
        Lod lod = build_lod(*session, c, 2);
        double sum = 0;
        for (int node : lod.cut.box_nodes) sum += errors[std::size_t(node)];
        EXPECT_EQ(lod.depth_error, sum) << c;
        EXPECT_EQ(statistic(lod, "depth_error"), format_number(sum)) << c;
        coarsest = sum;
    }
    EXPECT_EQ(build_lod(*session, 0, 2).depth_error, 0);
    EXPECT_GT(coarsest, 0);  // the one box hides the building's recesses
    EXPECT_EQ(coarsest, errors[0]);
}

TEST(LodBuilder, IntermediateLevelKeepsUpperGeometryAndBoxesTheRest) {
    Model model = test::lod_test_building();
    auto session = start_lod(model, small_parameters(), 2);
    // Level values top-down: Lot 3; Ground, House 2; Walls, Roof, Windows 1; each Window 0.
    session->input.parameters.crop_faces = false;  // the manual's six quads per box
    Lod lod = build_lod(*session, 2, 2);
    EXPECT_EQ(statistic(lod, "nodes_with_box"), "3");       // Walls, Roof, Windows
    EXPECT_EQ(statistic(lod, "nodes_with_geometry"), "1");  // Ground keeps its quad
    EXPECT_EQ(statistic(lod, "faces_lod"), "19");
    EXPECT_EQ(lod.model.nodes.size(), 6u);  // Lot, Ground, House, Walls, Roof, Windows
    EXPECT_TRUE(lod.model.is_lod);
    Lod windows_only = build_lod(*session, 1, 2);
    EXPECT_EQ(statistic(windows_only, "nodes_with_box"), "3");  // the three panes
    EXPECT_EQ(statistic(windows_only, "faces_lod"), std::to_string(1 + 4 + 2 + 3 * 6));
}

// Cropping keeps each face's rectangle of covered texels and drops faces that
// cover nothing: fewer faces and texels, the same picture. Not the same bytes:
// a smaller quad interpolates its uvs and depths with other roundings, coplanar
// faces of neighbouring boxes then win their depth ties differently, and coarser
// mip levels average other neighbours (docs/design.md: Atlas).
TEST(LodBuilder, CroppingDropsUncoveredFacesAndKeepsThePicture) {
    Model model = test::lod_test_building();
    LodParameters whole = small_parameters();
    whole.crop_faces = false;
    auto cropped_session = start_lod(model, small_parameters(), 2),
         whole_session = start_lod(model, whole, 2);
    Lod cropped = build_lod(*cropped_session, 2, 2), uncropped = build_lod(*whole_session, 2, 2);
    EXPECT_LT(std::stoi(statistic(cropped, "faces_lod")), std::stoi(statistic(uncropped, "faces_lod")));
    EXPECT_LT(cropped.face_texels, uncropped.face_texels);
    EXPECT_LT(page_texels(cropped.atlas), page_texels(uncropped.atlas));
    for (RenderMode mode : {RenderMode::normal, RenderMode::parallax, RenderMode::pom, RenderMode::albedo}) {
        cropped_session->input.parameters.render_mode = whole_session->input.parameters.render_mode = mode;
        Image8 a = render_lod_preview(cropped, *cropped_session->input.model,
                                      cropped_session->input.parameters, 240, 180, 2),
               b = render_lod_preview(uncropped, *whole_session->input.model, whole_session->input.parameters,
                                      240, 180, 2);
        std::size_t same = 0, pixels = a.pixels.size() / 3;
        double error = 0;
        for (std::size_t i = 0; i < pixels; ++i) {
            auto pixel_a = a.pixels.begin() + std::ptrdiff_t(i * 3),
                 pixel_b = b.pixels.begin() + std::ptrdiff_t(i * 3);
            same += std::equal(pixel_a, pixel_a + 3, pixel_b);
            for (int c = 0; c < 3; ++c)
                error += std::abs(int(a.pixels[i * 3 + c]) - int(b.pixels[i * 3 + c]));
        }
        // Measured: albedo all pixels equal, normal and parallax 99.998 %, pom 99.6 % (its rays reach the
        // gutters).
        EXPECT_GE(double(same) / double(pixels), 0.995) << render_mode_name(mode);
        EXPECT_LT(error / double(3 * pixels), 0.2)
            << render_mode_name(mode);  // mean difference in levels of 255
    }
}

// Flat faces (docs/design.md: Atlas): faces of at most `flat_faces` texels
// are drawn from one 4x4 swatch of their mean colour, all four uvs at its
// centre, so bilinear filtering reads only the swatch and mip level 0 is
// chosen (the uvs do not change over the face); no gutter, fewer texels.
TEST(LodBuilder, FlatFacesDrawOneColourFromAlignedSwatches) {
    Model model = test::lod_test_building();
    LodParameters plain = small_parameters(), flat = small_parameters();
    plain.min_texture_size = flat.min_texture_size = 16;
    flat.flat_faces = 64;  // every face of this small sizing, where at least half covered
    auto plain_session = start_lod(model, plain, 2), flat_session = start_lod(model, flat, 2);
    Lod with_texels = build_lod(*plain_session, 2, 2), with_swatches = build_lod(*flat_session, 2, 2);
    const int flat_faces = std::stoi(statistic(with_swatches, "flat_faces")),
              swatches = std::stoi(statistic(with_swatches, "swatches"));
    EXPECT_EQ(statistic(with_texels, "flat_faces"), "0");
    EXPECT_GE(flat_faces, 5);
    EXPECT_GE(swatches, 1);
    EXPECT_LT(swatches, flat_faces);  // faces of one colour share their swatch
    EXPECT_EQ(statistic(with_swatches, "faces_lod"), statistic(with_texels, "faces_lod"));
    EXPECT_LT(page_texels(with_swatches.atlas), page_texels(with_texels.atlas));
    EXPECT_LT(std::stoull(statistic(with_swatches, "gutter_texels")),
              std::stoull(statistic(with_texels, "gutter_texels")));

    // Every quad whose uvs are all one point samples a uniform, aligned, opaque
    // swatch, with the flat normal and height 1, and exactly its colour.
    int flat_quads = 0;
    for (const Node& node : with_swatches.model.nodes)
        for (const Primitive& primitive : node.primitives) {
            if (primitive.uvs.empty()) continue;
            const Material& material = with_swatches.model.materials[std::size_t(primitive.material)];
            if (material.height_texture < 0) continue;  // a kept node's own material, not a page
            const Texture& color = with_swatches.model.textures[std::size_t(material.base_color_texture)];
            const Texture& normal = with_swatches.model.textures[std::size_t(material.normal_texture)];
            const Texture& height = with_swatches.model.textures[std::size_t(material.height_texture)];
            for (std::size_t q = 0; q + 4 <= primitive.uvs.size(); q += 4) {
                const Eigen::Vector2f uv = primitive.uvs[q];
                if (!std::all_of(primitive.uvs.begin() + std::ptrdiff_t(q),
                                 primitive.uvs.begin() + std::ptrdiff_t(q + 4),
                                 [&](const Eigen::Vector2f& corner) { return corner == uv; }))
                    continue;
                ++flat_quads;
                const float cx = uv.x() * float(color.image.width) - 2,
                            cy = uv.y() * float(color.image.height) - 2;
                ASSERT_EQ(cx, std::floor(cx));
                const int x0 = int(cx), y0 = int(cy);
                EXPECT_EQ(x0 % 4, 0);
                EXPECT_EQ(y0 % 4, 0);
                const std::uint8_t* swatch = color.image.at(x0, y0);
                EXPECT_EQ(swatch[3], 255);
                for (int y = y0; y < y0 + 4; ++y)
                    for (int x = x0; x < x0 + 4; ++x) {
                        EXPECT_TRUE(std::equal(swatch, swatch + 4, color.image.at(x, y)));
                        EXPECT_EQ(normal.image.at(x, y)[0], 128);
                        EXPECT_EQ(normal.image.at(x, y)[2], 255);
                        EXPECT_EQ(height.image16.at(x, y)[0], 65535);
                    }
                const MipTexture texture = make_texture(color.image, ColorSpace::srgb, Wrap::clamp);
                const Eigen::Vector4f sampled =
                    sample(texture, uv, mip_level(texture, Eigen::Vector2f::Zero(), Eigen::Vector2f::Zero()));
                for (int c = 0; c < 3; ++c) EXPECT_EQ(sampled[c], srgb_to_linear(swatch[c]));
            }
        }
    EXPECT_EQ(flat_quads, flat_faces);

    // The picture keeps each face's colour on average; misplaced uvs would draw other texels.
    plain_session->input.parameters.render_mode = flat_session->input.parameters.render_mode =
        RenderMode::albedo;
    Image8 a = render_lod_preview(with_texels, *plain_session->input.model, plain_session->input.parameters,
                                  240, 180, 2),
           b = render_lod_preview(with_swatches, *flat_session->input.model, flat_session->input.parameters,
                                  240, 180, 2);
    double error = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) error += std::abs(int(a.pixels[i]) - int(b.pixels[i]));
    EXPECT_GT(error, 0);
    EXPECT_LT(error / double(a.pixels.size()), 2.0);  // mean difference in levels of 255
}

namespace {

// Two facades, each a wall with a window niche whose back wall's colour ramps
// along x and y, one niche 0.5 m deep and one 0.15 m: seen at a slant, the
// back wall moves against the opening by its depth, and the reveals hide some.
Model recessed_facades() {
    Model model;
    model.source = "recessed-facades";
    add_node(model, -1, "Lot");
    model.nodes[0].rule = "Lot";
    Material frame, wall;
    frame.base_color = {0.05f, 0.05f, 0.05f, 1};
    wall.base_color_texture = 0;
    model.materials = {frame, wall};
    Texture ramp{"ramp.png", Image8(16, 16, 4, 255), {}};
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            ramp.image.at(x, y)[0] = std::uint8_t(x * 17);
            ramp.image.at(x, y)[1] = std::uint8_t(y * 17);
        }
    model.textures.push_back(ramp);
    for (float x : {0.0f, 3.0f}) {
        const float z = x == 0 ? 0.5f : 0.15f, l = x + 0.5f,
                    r = x + 1.5f;  // the opening: [l, r] x [0.5, 1.5]
        int facade = add_node(model, 0, "Facade");
        model.nodes[facade].rule = "Facade";
        test::add_quad(model.nodes[test::add_part(model, facade, "Back", 1)].primitives[0], {l, 0.5f, 0},
                       {r, 0.5f, 0}, {r, 1.5f, 0}, {l, 1.5f, 0});
        Primitive& f = model.nodes[test::add_part(model, facade, "Wall", 0)].primitives[0];
        test::add_quad(f, {x, 0, z}, {x + 2, 0, z}, {x + 2, 0.5f, z}, {x, 0.5f, z});
        test::add_quad(f, {x, 1.5f, z}, {x + 2, 1.5f, z}, {x + 2, 2, z}, {x, 2, z});
        test::add_quad(f, {x, 0.5f, z}, {l, 0.5f, z}, {l, 1.5f, z}, {x, 1.5f, z});
        test::add_quad(f, {r, 0.5f, z}, {x + 2, 0.5f, z}, {x + 2, 1.5f, z}, {r, 1.5f, z});
        // The reveals, from the opening back to the niche's wall.
        test::add_quad(f, {l, 0.5f, z}, {l, 0.5f, 0}, {l, 1.5f, 0}, {l, 1.5f, z});
        test::add_quad(f, {r, 0.5f, 0}, {r, 0.5f, z}, {r, 1.5f, z}, {r, 1.5f, 0});
        test::add_quad(f, {l, 0.5f, 0}, {l, 0.5f, z}, {r, 0.5f, z}, {r, 0.5f, 0});
        test::add_quad(f, {l, 1.5f, z}, {l, 1.5f, 0}, {r, 1.5f, 0}, {r, 1.5f, z});
    }
    validate_model(model);
    return model;
}

// Mean absolute difference of two renders over the pixels `where` marks, in levels of 255.
double mean_difference(const Image8& a, const Image8& b, const std::vector<bool>& where) {
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        if (where[i / 3]) {
            sum += std::abs(int(a.pixels[i]) - int(b.pixels[i]));
            ++count;
        }
    return sum / double(std::max<std::size_t>(count, 1));
}

}  // namespace

// A level's pages state the depth of their height maps in metres, so parallax
// and POM move each face's texels by what lies behind it (docs/design.md:
// Rendering): both come nearer the original than flat normal mapping, which
// the manual's page-relative offsets did not.
TEST(LodBuilder, ParallaxOnPagesShowsTheRecessesBehindTheFaces) {
    Model model = recessed_facades();
    LodParameters p = small_parameters();
    p.resolution = 512;
    auto session = start_lod(model, p, 2);
    Lod lod = build_lod(*session, 2, 2);  // top-down: the facades are level 1 and closed from level 2
    ASSERT_EQ(statistic(lod, "nodes_with_box"), "2");
    // The pages' depth is the deepest face's: the sides, across the 2 m facade; the niches are 0.5 and 0.15
    // m.
    for (const Material& material : lod.model.materials)
        EXPECT_NEAR(material.height_depth, 2, 1e-5) << material.name;
    auto render_model = [](const Model& m, RenderMode mode) {
        RenderSettings settings;
        settings.mode = mode;
        settings.camera.position = {5.5f, 1.8f, 3.5f};
        settings.camera.target = {2.5f, 1, 0.5f};
        settings.light.position = {2.5f, 10, 10};
        Frame frame = make_frame(320, 200, {1, 1, 1});
        render(make_drawable_model(m, nullptr, 2)->drawable.batches, settings, frame);
        return frame_to_srgb8(frame);
    };
    const Image8 original = render_model(model, RenderMode::normal);
    Model page_uv = lod.model;  // the manual's offsets, in page uv
    for (Material& material : page_uv.materials) material.height_depth = 0;
    const Image8 normal = render_model(lod.model, RenderMode::normal),
                 parallax = render_model(lod.model, RenderMode::parallax),
                 pom = render_model(lod.model, RenderMode::pom),
                 page_uv_parallax = render_model(page_uv, RenderMode::parallax);
    // Judged where the modes differ: the pixels whose texels come from behind the faces.
    std::vector<bool> moved(std::size_t(original.width) * std::size_t(original.height), false);
    for (std::size_t i = 0; i < normal.pixels.size(); ++i)
        for (const Image8* image : {&parallax, &pom, &page_uv_parallax})
            moved[i / 3] = moved[i / 3] || image->pixels[i] != normal.pixels[i];
    ASSERT_GT(std::count(moved.begin(), moved.end(), true), 1000);
    const double error_normal = mean_difference(normal, original, moved),
                 error_parallax = mean_difference(parallax, original, moved),
                 error_pom = mean_difference(pom, original, moved),
                 error_page_uv = mean_difference(page_uv_parallax, original, moved);
    std::cout << "mean difference: normal " << error_normal << ", parallax " << error_parallax << ", pom "
              << error_pom << ", parallax in page uv " << error_page_uv << ", over "
              << std::count(moved.begin(), moved.end(), true) << " pixels\n";
    EXPECT_LT(error_parallax, 0.8 * error_normal);   // measured 0.62
    EXPECT_LT(error_pom, 0.8 * error_normal);        // 0.69
    EXPECT_LT(error_parallax, 0.7 * error_page_uv);  // 0.51
}

TEST(LodBuilder, AnLodCannotBeSimplifiedAgain) {
    Model model = test::lod_test_building();
    model.is_lod = true;
    EXPECT_THROW(start_lod(model, small_parameters(), 1), InputError);
}

TEST(LodBuilder, AFramingDistanceBeyondTheDistanceRangeIsRefused) {
    Model model = test::lod_test_building();  // 1.9 billion metres wide, seen through 0.1 degrees
    const Bounds bounds = model_bounds(model);
    const float scale = 1.9e9f / bounds.size().maxCoeff();
    for (Node& node : model.nodes)
        for (Primitive& primitive : node.primitives)
            for (Eigen::Vector3f& p : primitive.positions) p = (p - (bounds.min + bounds.max) / 2) * scale;
    for (Node& node : model.nodes) node.scope.reset();
    LodParameters p = small_parameters();
    p.fovy = 0.1f;
    EXPECT_NE(test::input_error_of([&] {
                  start_lod(model, p, 1);
              }).find("the distance that frames it at fovy 0.1, "),
              std::string::npos)
        << test::input_error_of([&] { start_lod(model, p, 1); });
    p.distance = 1e12f;  // given, it is used
    EXPECT_NO_THROW(start_lod(model, p, 1));
}

TEST(LodBuilder, SameResultForAnyThreadCount) {
    Model model = test::lod_test_building();
    LodParameters p = small_parameters();
    p.box_kind = BoxKind::minimal;
    auto one = start_lod(model, p, 1);
    auto three = start_lod(model, p, 3);
    Lod a = build_lod(*one, 2, 1), b = build_lod(*three, 2, 3);
    ASSERT_EQ(a.model.textures.size(), b.model.textures.size());
    for (std::size_t i = 0; i < a.model.textures.size(); ++i) {
        EXPECT_EQ(a.model.textures[i].image.pixels, b.model.textures[i].image.pixels);
        EXPECT_EQ(a.model.textures[i].image16.pixels, b.model.textures[i].image16.pixels);
    }
    ASSERT_EQ(a.model.nodes.size(), b.model.nodes.size());
    for (std::size_t i = 0; i < a.model.nodes.size(); ++i)
        for (std::size_t k = 0; k < a.model.nodes[i].primitives.size(); ++k)
            EXPECT_EQ(a.model.nodes[i].primitives[k].positions, b.model.nodes[i].primitives[k].positions);
}

TEST(LodBuilder, ExportWritesEveryFileAndReadsBackAsAnLod) {
    Model model = test::lod_test_building();
    auto session = start_lod(model, small_parameters(), 2);
    Lod lod = build_lod(*session, 2, 2);
    auto folder = test::scratch_folder("lod_export");
    Image8 preview = render_lod_preview(lod, *session->input.model, session->input.parameters, 64, 48, 2);
    export_lod(lod, session->input.parameters, folder.string(), "house", preview, 2);
    for (const char* file :
         {"house.gltf", "house.bin", "house_color_0.png", "house_normal_0.png", "house_height_0.png",
          "house.params.txt", "house.preview.png", "house.stats.txt"})
        EXPECT_TRUE(std::filesystem::exists(folder / file)) << file;
    Model back = load_model((folder / "house.gltf").string());
    EXPECT_TRUE(back.is_lod);
    EXPECT_EQ(mesh_counts(back).faces, mesh_counts(lod.model).faces);
    EXPECT_FALSE(back.textures[2].image16.empty());  // the height page keeps 16 bits
    EXPECT_EQ(back.textures[2].image16.pixels, lod.model.textures[2].image16.pixels);
    for (int page_texture = 0; page_texture < 3; ++page_texture)  // pages are sampled clamped to their edge
        EXPECT_EQ(back.textures[std::size_t(page_texture)].wrap, Wrap::clamp) << page_texture;
    EXPECT_EQ(texture_digest(back.textures[0]), texture_digest(lod.model.textures[0]));
    // Page materials come first: cut out where uncovered, both sides drawn, as boxlod measures them.
    EXPECT_EQ(back.materials[0].alpha_mode, AlphaMode::mask);
    EXPECT_EQ(back.materials[0].alpha_cutoff, 0.5f);
    EXPECT_TRUE(back.materials[0].double_sided);
    EXPECT_THROW(start_lod(back, small_parameters(), 1), InputError);
    LodParameters saved = load_parameters((folder / "house.params.txt").string());
    EXPECT_EQ(saved.current_level, 2);
    EXPECT_EQ(saved.distance, session->input.parameters.distance);
    // As one .glb: the pages inside, the same LoD read back.
    export_lod(lod, session->input.parameters, folder.string(), "packed", preview, 2, true);
    EXPECT_TRUE(std::filesystem::exists(folder / "packed.glb"));
    EXPECT_FALSE(std::filesystem::exists(folder / "packed_color_0.png"));
    Model packed = load_model((folder / "packed.glb").string());
    EXPECT_EQ(mesh_counts(packed).faces, mesh_counts(lod.model).faces);
    EXPECT_EQ(texture_digest(packed.textures[0]), texture_digest(lod.model.textures[0]));
}

// Golden renders of an LoD in every render mode (regenerate: BOXLOD_UPDATE_GOLDEN=1 ctest -R LodGolden).
TEST(LodGolden, EachRenderMode) {
    Model model = test::lod_test_building();
    for (RenderMode mode :
         {RenderMode::untextured, RenderMode::normal, RenderMode::parallax, RenderMode::pom}) {
        LodParameters p = small_parameters();
        p.render_mode = mode;
        p.resolution = 128;
        auto session = start_lod(model, p, 2);
        // Level 2 boxes the roof, whose heights vary (level 1 boxes only the flat panes, where parallax draws
        // as normal mapping).
        Lod lod = build_lod(*session, 2, 2);
        test::expect_golden(
            render_lod_preview(lod, *session->input.model, session->input.parameters, 120, 90, 2),
            std::string("lod_") + render_mode_name(mode));
    }
}

// The FZK-Haus's glass (IFC opacity 0.12) is blended: the original shows what
// lies behind its windows, and a baked level records the glass over the rooms.
TEST(LodGolden, FzkHausGlassIsSeeThrough) {
    Model model = load_model(test::fzk_haus_ifc);
    LodParameters p = small_parameters();
    p.resolution = 128;
    auto session = start_lod(model, p, 2);
    Image8 original = render_lod_preview(build_lod(*session, 0, 2), *session->input.model,
                                         session->input.parameters, 200, 150, 2);
    test::expect_golden(original, "lod_fzk_glass_original");
    test::expect_golden(render_lod_preview(build_lod(*session, 2, 2), *session->input.model,
                                           session->input.parameters, 200, 150, 2),
                        "lod_fzk_glass_level2");
    int glass = 0;
    for (Material& material : model.materials)
        if (material.alpha_mode == AlphaMode::blend) {
            material.alpha_mode = AlphaMode::opaque;
            ++glass;
        }
    EXPECT_GT(glass, 0);
    auto opaque_session = start_lod(model, p, 2);
    EXPECT_NE(render_lod_preview(build_lod(*opaque_session, 0, 2), *opaque_session->input.model,
                                 opaque_session->input.parameters, 200, 150, 2)
                  .pixels,
              original.pixels);
}

// The defaults (docs/design.md: Defaults): the FZK-Haus's chain that pays its
// way as `build --all-levels` makes it, levels sized per level, seen from the
// first level's view. Level 2 keeps what is cheaper than its box and boxes the
// rest; level 4 is sized for 8x the distance.
TEST(LodGolden, FzkHausDefaultChain) {
    Model model = load_model(test::fzk_haus_ifc);
    LodParameters p;
    p.resolution = 128;
    Chain chain(model, p, 2);  // level_distances auto
    for (int c : {2, 4}) {
        Lod lod = build_lod(chain.for_level(c), c, 2);
        EXPECT_LT(combined_cost({&lod.cost}).bytes(), chain.first->derived.original_cost.bytes())
            << "level " << c;
        test::expect_golden(render_lod_preview(lod, chain.model, chain.parameters(), 200, 150, 2),
                            "lod_fzk_default_chain_level" + std::to_string(c));
    }
}

// Real data: the FZK-Haus at every level of every level mode and box kind.
TEST(LodBuilder, FzkHausBuildsAtEveryLevelOfEveryModeAndBoxKind) {
    Model model = load_model(test::fzk_haus_ifc);
    std::size_t original_faces = mesh_counts(model).faces;
    for (BoxKind kind : {BoxKind::scope, BoxKind::expanded, BoxKind::minimal}) {
        auto boxes = node_boxes(model, kind, 2);
        for (LevelMode mode :
             {LevelMode::top_down, LevelMode::bottom_up, LevelMode::bottom_up_siblings, LevelMode::box_volume,
              LevelMode::box_area, LevelMode::box_diagonal, LevelMode::box_max_extent}) {
            LodParameters p = small_parameters();
            p.box_kind = kind;
            p.level_mode = mode;
            p.render_mode = RenderMode::untextured;
            auto session = start_lod(model, p, 2, &boxes);
            int n = session->derived.levels.obtained_levels;
            for (int c = 0; c <= n; ++c) {
                Lod lod = build_lod(*session, c, 2);
                std::size_t faces = mesh_counts(lod.model).faces;
                if (c == 0) {
                    EXPECT_EQ(faces, original_faces);
                }
                if (c == n) {
                    EXPECT_EQ(faces, 6u) << level_mode_name(mode) << " " << box_kind_name(kind);
                }
            }
        }
    }
    // And once with baking, the default mode.
    LodParameters p = small_parameters();
    auto session = start_lod(model, p, 2);
    Lod lod = build_lod(*session, 3, 2);
    EXPECT_FALSE(lod.atlas.pages.empty());
}
