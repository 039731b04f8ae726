#include "toolkit/formats/cityjson_import.h"

#include "base/memory_budget.h"
#include "renderer/image.h"
#include "test_support.h"
#include "toolkit/formats/gltf_io.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/model/model_subtree.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

namespace boxlod {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// A CityJSON 2.0 file of these objects over these vertices (millimetres).
json city(const json& objects, const json& vertices, const json& translate = {0, 0, 0}) {
    return {{"type", "CityJSON"},
            {"version", "2.0"},
            {"transform", {{"scale", {0.001, 0.001, 0.001}}, {"translate", translate}}},
            {"CityObjects", objects},
            {"vertices", vertices}};
}

Model read(const json& file, const std::string& name, const std::string& lod = "") {
    const fs::path path = test::scratch_folder("cityjson_" + name) / (name + ".city.json");
    test::write_text(path, file.dump());
    return import_cityjson(path.string(), lod);
}

int node_named(const Model& model, const std::string& name) {
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        if (model.nodes[n].name == name) return int(n);
    return -1;
}

double area(const Node& node) {
    double sum = 0;
    for (const Primitive& p : node.primitives)
        for (std::size_t i = 0; i < p.indices.size(); i += 3)
            sum += (p.positions[p.indices[i + 1]] - p.positions[p.indices[i]])
                       .cross(p.positions[p.indices[i + 2]] - p.positions[p.indices[i]])
                       .norm() /
                   2;
    return sum;
}

std::size_t triangles(const Model& model) {
    std::size_t count = 0;
    for (const Node& node : model.nodes)
        for (const Primitive& p : node.primitives) count += p.triangle_count();
    return count;
}

// A unit square: four vertex indices from `first`.
const json square_vertices = {{0, 0, 0}, {1000, 0, 0}, {1000, 1000, 0}, {0, 1000, 0}};
json surface(int first) { return {{first, first + 1, first + 2, first + 3}}; }

// A building of one LoD 1 MultiSurface.
json building(const json& boundaries) {
    return {{"type", "Building"},
            {"geometry", {{{"type", "MultiSurface"}, {"lod", "1"}, {"boundaries", boundaries}}}}};
}

TEST(CityJsonImport, ObjectsHangUnderTheirParentsWithTheirTypes) {
    const json objects = {
        {"house", {{"type", "Building"}, {"children", {"east", "west"}}}},
        {"east",
         {{"type", "BuildingPart"},
          {"parents", {"house"}},
          {"geometry", {{{"type", "MultiSurface"}, {"lod", "2"}, {"boundaries", {surface(0)}}}}}}},
        {"west",
         {{"type", "BuildingPart"},
          {"parents", {"house"}},
          {"geometry", {{{"type", "MultiSurface"}, {"lod", "2"}, {"boundaries", {surface(0)}}}}}}}};
    const Model model = read(city(objects, square_vertices), "parts");
    const int house = node_named(model, "house"), east = node_named(model, "east"),
              west = node_named(model, "west");
    ASSERT_GE(house, 0);
    EXPECT_EQ(model.nodes[std::size_t(house)].parent, 0);
    EXPECT_EQ(model.nodes[std::size_t(east)].parent, house);
    EXPECT_EQ(model.nodes[std::size_t(west)].parent, house);
    EXPECT_EQ(model.nodes[std::size_t(house)].rule, "Building");
    EXPECT_EQ(model.nodes[std::size_t(east)].rule, "BuildingPart");
    EXPECT_FALSE(model.nodes[std::size_t(house)].has_geometry());
    EXPECT_NEAR(area(model.nodes[std::size_t(east)]), 1, 1e-6);
    EXPECT_EQ(tree_depth(model), 2);
}

TEST(CityJsonImport, AWindowSitsUnderTheWallItIsCutFrom) {
    // A 4 x 3 m wall facing -y with a 1 x 1 m window hole, and the window.
    const json vertices = {{0, 0, 0},       {4000, 0, 0},    {4000, 0, 3000}, {0, 0, 3000},
                           {1000, 0, 1000}, {1000, 0, 2000}, {2000, 0, 2000}, {2000, 0, 1000}};
    const json geometry = {{"type", "MultiSurface"},
                           {"lod", "3"},
                           {"boundaries", {{{0, 1, 2, 3}, {4, 5, 6, 7}}, {{4, 7, 6, 5}}}},
                           {"semantics",
                            {{"surfaces", {{{"type", "WallSurface"}}, {{"type", "Window"}, {"parent", 0}}}},
                             {"values", {0, 1}}}}};
    const Model model =
        read(city({{"shed", {{"type", "Building"}, {"geometry", {geometry}}}}}, vertices), "window");
    const int wall = node_named(model, "WallSurface 0"), window = node_named(model, "Window 1");
    ASSERT_GE(wall, 0);
    ASSERT_GE(window, 0);
    EXPECT_EQ(model.nodes[std::size_t(window)].parent, wall);
    EXPECT_EQ(model.nodes[std::size_t(wall)].parent, node_named(model, "shed"));
    EXPECT_EQ(model.nodes[std::size_t(window)].rule, "Window");
    EXPECT_NEAR(area(model.nodes[std::size_t(wall)]), 11, 1e-5);
    EXPECT_NEAR(area(model.nodes[std::size_t(window)]), 1, 1e-5);
    EXPECT_EQ(tree_depth(model), 3);
    // Untextured and without a material: drawn in the semantic type's colour.
    const Material& wall_material =
        model.materials[std::size_t(model.nodes[std::size_t(wall)].primitives[0].material)];
    const Material& window_material =
        model.materials[std::size_t(model.nodes[std::size_t(window)].primitives[0].material)];
    EXPECT_NE(wall_material.base_color, window_material.base_color);
    // z up becomes y up: the wall faces -y in the file, +z in the model.
    const Primitive& p = model.nodes[std::size_t(wall)].primitives[0];
    const Eigen::Vector3f normal = (p.positions[p.indices[1]] - p.positions[p.indices[0]])
                                       .cross(p.positions[p.indices[2]] - p.positions[p.indices[0]]);
    EXPECT_GT(normal.z(), 0);
    EXPECT_EQ(p.polygon_count, 1u);
    // Parents that form a cycle, and a chain of them deeper than any reader recurses.
    const auto parents_problem = [&](json surfaces) {
        json chained = geometry;
        chained["semantics"]["surfaces"] = std::move(surfaces);
        return test::input_error_of([&] {
            read(city({{"shed", {{"type", "Building"}, {"geometry", {chained}}}}}, vertices), "window");
        });
    };
    EXPECT_NE(parents_problem({{{"type", "WallSurface"}, {"parent", 1}}, {{"type", "Window"}, {"parent", 0}}})
                  .find("semantics: surface 1's parents form a cycle"),
              std::string::npos);
    json chain = json::array();
    for (int i = 0; i < 300; ++i) chain.push_back({{"type", "Window"}, {"parent", i + 1}});
    chain.push_back({{"type", "WallSurface"}});
    EXPECT_NE(parents_problem(chain).find("parents nested more than 200 levels deep"), std::string::npos)
        << parents_problem(chain);
}

TEST(CityJsonImport, TexturedSurfacesAndAMissingImage) {
    const fs::path folder = test::scratch_folder("cityjson_textured");
    Image8 image(2, 2, 4);  // as read_image gives it: RGBA
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = i % 4 == 3 ? 255 : std::uint8_t(40 * i);
    write_png((folder / "roof.png").string(), image);
    json file =
        city({{"roof",
               {{"type", "Building"},
                {"geometry",
                 {{{"type", "MultiSurface"},
                   {"lod", "2"},
                   {"boundaries", {surface(0), surface(4)}},
                   {"material", {{"colour", {{"values", {0, 0}}}}}},
                   {"texture", {{"photo", {{"values", {{{0, 0, 1, 2, 3}}, {{1, 0, 1, 2, 3}}}}}}}}}}}}}},
             {{0, 0, 0},
              {1000, 0, 0},
              {1000, 1000, 0},
              {0, 1000, 0},
              {0, 0, 100},
              {1000, 0, 100},
              {1000, 1000, 100},
              {0, 1000, 100}});
    file["appearance"] = {
        {"materials", {{{"name", "red"}, {"diffuseColor", {1, 0, 0}}, {"transparency", 0.25}}}},
        {"textures", {{{"type", "PNG"}, {"image", "roof.png"}}, {{"type", "PNG"}, {"image", "gone.png"}}}},
        {"vertices-texture", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}}};
    test::write_text(folder / "roof.city.json", file.dump());
    testing::internal::CaptureStderr();
    const Model model = import_cityjson((folder / "roof.city.json").string());
    const std::string warning = testing::internal::GetCapturedStderr();
    EXPECT_NE(warning.find("1 texture files are missing (gone.png)"), std::string::npos) << warning;
    EXPECT_EQ(std::count(warning.begin(), warning.end(), '\n'), 1);
    const Node& roof = model.nodes[std::size_t(node_named(model, "roof"))];
    ASSERT_EQ(roof.primitives.size(), 2u);
    const Primitive& textured = roof.primitives[0];
    const Material& photo = model.materials[std::size_t(textured.material)];
    ASSERT_GE(photo.base_color_texture, 0);
    EXPECT_EQ(model.textures[std::size_t(photo.base_color_texture)].image.pixels, image.pixels);
    EXPECT_EQ(model.read_files, std::vector<std::string>{(folder / "roof.png").string()});
    ASSERT_EQ(textured.uvs.size(), 4u);
    EXPECT_EQ(textured.uvs[0], Eigen::Vector2f(0, 1));  // CityGML's (0, 0) is the image's bottom left
    const Primitive& plain = roof.primitives[1];
    EXPECT_TRUE(plain.uvs.empty());
    const Material& red = model.materials[std::size_t(plain.material)];
    EXPECT_EQ(red.base_color_texture, -1);
    EXPECT_EQ(red.base_color, Eigen::Vector4f(1, 0, 0, 0.75f));
    EXPECT_EQ(red.alpha_mode, AlphaMode::blend);
    // Two textures of one image file (as a CityJSONSeq's features may name one atlas): one texture.
    file["appearance"]["textures"][1]["image"] = "./roof.png";
    test::write_text(folder / "twice.city.json", file.dump());
    const Model twice = import_cityjson((folder / "twice.city.json").string());
    EXPECT_EQ(twice.textures.size(), 1u);
    EXPECT_EQ(twice.nodes[std::size_t(node_named(twice, "roof"))].primitives.size(), 1u);
    // A name with a NUL would read roof.png: the file system takes a name up to it.
    file["appearance"]["textures"][1]["image"] = std::string("roof.png\0zz", 11);
    test::write_text(folder / "nul.city.json", file.dump());
    EXPECT_NE(test::input_error_of([&] {
                  import_cityjson((folder / "nul.city.json").string());
              }).find("appearance: texture 1 has no 'image' (a file name, without NUL)"),
              std::string::npos);
}

// A 10 m square with a 1 mm step in one corner, at the origin or 400 km out.
Model step_at(const json& translate, const std::string& name) {
    const json vertices = {{0, 0, 0},     {10000, 0, 0}, {10000, 10000, 0},
                           {1, 10000, 0}, {1, 10001, 0}, {0, 10001, 0}};
    return read(
        city({{"plot",
               {{"type", "Building"},
                {"geometry",
                 {{{"type", "MultiSurface"}, {"lod", "1"}, {"boundaries", {{{0, 1, 2, 3, 4, 5}}}}}}}}}},
             vertices, translate),
        name);
}

TEST(CityJsonImport, FarFromTheOriginReadsAsNearIt) {
    const Model near = step_at({0, 0, 0}, "near"), far = step_at({150000.25, 400000.25, 12}, "far");
    EXPECT_EQ(near.origin,
              Eigen::Vector3d(5, 0, -5));  // the middle of the ground rectangle in whole metres, y up
    EXPECT_EQ(far.origin, Eigen::Vector3d(150005, 12, -400005));
    const Primitive& a = near.nodes[1].primitives[0];
    const Primitive& b = far.nodes[1].primitives[0];
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (std::size_t i = 0; i < a.positions.size(); ++i)  // 0.25 m further from their origin, each
        EXPECT_LT((b.positions[i] - a.positions[i] - Eigen::Vector3f(0.25f, 0, -0.25f)).norm(), 1e-5f);
    // The 1 mm step survives: its two vertices differ by 1 mm in float.
    EXPECT_NEAR((b.positions[3] - b.positions[4]).norm(), 0.001, 1e-5);
}

TEST(CityJsonImport, GltfKeepsTheOriginAsTheRootsTranslation) {
    Model far = step_at({150000.25, 400000.25, 12}, "far_gltf");
    far.reference_system = "EPSG:7415";  // kept beside the origin, so `tiles` of the glb places it too
    const fs::path path = test::scratch_folder("cityjson_far_gltf_out") / "far.glb";
    save_model(far, path.string());
    const Model back = load_model(path.string());
    EXPECT_EQ(back.origin, far.origin);
    EXPECT_EQ(back.reference_system, "EPSG:7415");
    EXPECT_EQ(back.nodes.size(), far.nodes.size());
    EXPECT_EQ(back.nodes[1].primitives[0].positions, far.nodes[1].primitives[0].positions);
    // What any client sees: the scene's one node moves the model there.
    tinygltf::Model gltf;
    std::string error, warning;
    ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromFile(&gltf, &error, &warning, path.string()));
    const tinygltf::Node& root = gltf.nodes[std::size_t(gltf.scenes[0].nodes[0])];
    EXPECT_EQ(root.translation, std::vector<double>({150005, 12, -400005}));
}

// Instances place their template's points only: two templates over one pool,
// each placed by its matrix at its reference point (CityJSON 2.0, "Geometry templates").
TEST(CityJsonImport, GeometryInstancesPlaceTheirTemplates) {
    const json pool = {{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {2, 0, 0}, {0, 0, 2}};
    json file = city({}, {{0, 0, 0}, {10000, 0, 0}});
    file["geometry-templates"] = {
        {"templates",
         {{{"type", "MultiSurface"}, {"lod", "2"}, {"boundaries", {{{1, 2, 3}}}}},
          {{"type", "MultiSurface"}, {"lod", "2"}, {"boundaries", {{{4, 5, 6}}}}},
          {{"type", "MultiPoint"}, {"lod", "2"}, {"boundaries", {0, 1, 2, 3, 4, 5, 6}}}}},
        {"vertices-templates", pool}};
    const json identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const json thrice = {3, 0, 0, 0, 0, 3, 0, 0, 0, 0, 3, 0, 0, 0, 0, 1};
    auto tree = [](int shape, int reference, const json& matrix) {
        return json{{"type", "SolitaryVegetationObject"},
                    {"geometry",
                     {{{"type", "GeometryInstance"},
                       {"template", shape},
                       {"boundaries", {reference}},
                       {"transformationMatrix", matrix}}}}};
    };
    file["CityObjects"] = {{"small", tree(0, 0, identity)},
                           {"large", tree(1, 0, thrice)},
                           {"moved", tree(1, 1, identity)},
                           {"points", tree(2, 0, identity)}};  // draws nothing
    json projective = file;
    projective["CityObjects"]["small"]["geometry"][0]["transformationMatrix"][12] = 1;
    EXPECT_NE(test::input_error_of([&] {
                  read(projective, "instances_projective");
              }).find("'transformationMatrix' is not affine (its last row is not 0, 0, 0, 1)"),
              std::string::npos);
    const Model model = read(file, "instances");
    const Node& small = model.nodes[std::size_t(node_named(model, "small"))];
    const Node& large = model.nodes[std::size_t(node_named(model, "large"))];
    const Node& moved = model.nodes[std::size_t(node_named(model, "moved"))];
    EXPECT_NEAR(area(small), 0.5, 1e-6);
    EXPECT_NEAR(area(large), 18, 1e-5);  // 2 m^2 scaled by 3 in each direction
    EXPECT_NEAR(area(moved), 2, 1e-6);
    // Template point 4 and 1 are both (0, 0, 0): placed at the two reference points, 10 m apart.
    EXPECT_NEAR((moved.primitives[0].positions[0] - small.primitives[0].positions[0]).norm(), 10, 1e-5);
    EXPECT_EQ(triangles(model), 3u);
    // A CityJSONSeq keeps its templates in its first line, for every feature.
    json header = file;
    header["CityObjects"] = json::object();
    header["vertices"] = json::array();
    auto feature = [&](const std::string& id, int shape) {
        return json{{"type", "CityJSONFeature"},
                    {"id", id},
                    {"CityObjects", {{id, tree(shape, 0, thrice)}}},
                    {"vertices", {{0, 0, 0}}}};
    };
    const fs::path path = test::scratch_folder("cityjson_seq_instances") / "trees.city.jsonl";
    test::write_text(path,
                     header.dump() + "\n" + feature("a", 0).dump() + "\n" + feature("b", 1).dump() + "\n");
    const Model seq = load_model(path.string());
    EXPECT_NEAR(area(seq.nodes[std::size_t(node_named(seq, "a"))]), 4.5, 1e-5);
    EXPECT_NEAR(area(seq.nodes[std::size_t(node_named(seq, "b"))]), 18, 1e-5);
}

// 100 instances of a template of 1,000 triangles copy 300,000 points, some 48 MB: over a 10 MB budget the
// file is refused before any geometry is read (object "a", read first, would fail on its vertex index),
// and instances of an LoD the reading leaves out do not count.
TEST(CityJsonImport, InstancesBeyondTheMemoryBudgetAreRefusedBeforeAnyIsRead) {
    test::MemoryBudgetScope restore;
    set_memory_budget(10e6);
    json file =
        city({{"a", building(json::array({json::array({json::array({0, 1, 99})})}))}}, square_vertices);
    file["geometry-templates"] = {
        {"templates", json::array({{{"type", "MultiSurface"}, {"lod", "1"}, {"boundaries", json::array()}}})},
        {"vertices-templates", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}};
    for (int i = 0; i < 1000; ++i)
        file["geometry-templates"]["templates"][0]["boundaries"].push_back(
            json::array({json::array({0, 1, 2})}));
    const json identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (int i = 0; i < 100; ++i)
        file["CityObjects"]["tree " + std::to_string(i)] = {
            {"type", "SolitaryVegetationObject"},
            {"geometry", json::array({{{"type", "GeometryInstance"},
                                       {"lod", "1"},
                                       {"template", 0},
                                       {"boundaries", {0}},
                                       {"transformationMatrix", identity}}})}};
    const std::string message = test::input_error_of([&] { read(file, "instances_budget"); });
    EXPECT_NE(message.find("instances_budget.city.json: the GeometryInstances' copies of their templates"),
              std::string::npos)
        << message;
    file["CityObjects"]["a"] = building(json::array({surface(0)}));
    file["CityObjects"]["a"]["geometry"][0]["lod"] = "2";
    EXPECT_EQ(triangles(read(file, "instances_other_lod", "2")), 2u);
}

TEST(CityJsonImport, EachObjectsFinestLodUnlessOneIsAsked) {
    const json geometries = {
        {{"type", "MultiSurface"}, {"lod", "1.2"}, {"boundaries", {surface(0)}}},
        {{"type", "MultiSurface"}, {"lod", "2.2"}, {"boundaries", {surface(0), surface(0)}}}};
    const json file = city({{"b", {{"type", "Building"}, {"geometry", geometries}}}}, square_vertices);
    EXPECT_EQ(read(file, "lod_finest").nodes[1].primitives[0].polygon_count, 2u);
    EXPECT_EQ(read(file, "lod_asked", "1.2").nodes[1].primitives[0].polygon_count, 1u);
    EXPECT_NE(test::input_error_of([&] {
                  read(file, "lod_absent", "3");
              }).find("no surface of LoD 3 (the file has LoD 1.2, 2.2)"),
              std::string::npos);
    // One LoD spelt twice is drawn once: the spelling asked, else the first (from a hostile-input run,
    // which saw "2.2" and "2.20" drawn over each other).
    json twice = geometries;
    twice[0]["lod"] = "2.20";
    twice[0]["boundaries"] = {surface(0), surface(0), surface(0)};
    const json spelt = city({{"b", {{"type", "Building"}, {"geometry", twice}}}}, square_vertices);
    EXPECT_EQ(read(spelt, "lod_spelt_first").nodes[1].primitives.size(), 1u);
    EXPECT_EQ(read(spelt, "lod_spelt_first").nodes[1].primitives[0].polygon_count, 3u);
    EXPECT_EQ(read(spelt, "lod_spelt_asked", "2.2").nodes[1].primitives[0].polygon_count, 2u);
    EXPECT_EQ(read(spelt, "lod_spelt_other", "2.200").nodes[1].primitives[0].polygon_count, 3u);
    // "2.2.2" was read as 2.2, so both geometries were drawn over each other.
    json wrong = geometries;
    wrong[0]["lod"] = "2.2.2";
    EXPECT_NE(
        test::input_error_of([&] {
            read(city({{"b", {{"type", "Building"}, {"geometry", wrong}}}}, square_vertices), "lod_wrong");
        })
            .find("CityObjects 'b': geometry 0: 'lod' \"2.2.2\" is not an LoD (0 to 4, or a refinement such "
                  "as 2.2)"),
        std::string::npos);
    for (const json& lod : {json("999"), json(""), json(-1), json(nullptr), json("0x2"), json("2e0")}) {
        wrong[0]["lod"] = lod;
        EXPECT_NE(test::input_error_of([&] {
                      read(city({{"b", {{"type", "Building"}, {"geometry", wrong}}}}, square_vertices),
                           "lod_wrong");
                  }).find("is not an LoD"),
                  std::string::npos)
            << lod;
    }
}

TEST(CityJsonImport, CityJsonSeqFeaturesEachBringTheirVertices) {
    const json header = {{"type", "CityJSON"},
                         {"version", "2.0"},
                         {"transform", {{"scale", {0.001, 0.001, 0.001}}, {"translate", {0, 0, 0}}}},
                         {"CityObjects", json::object()},
                         {"vertices", json::array()}};
    auto feature = [](const std::string& id, int x) {
        return json{
            {"type", "CityJSONFeature"},
            {"id", id},
            {"CityObjects",
             {{id,
               {{"type", "Building"},
                {"geometry", {{{"type", "MultiSurface"}, {"lod", "1"}, {"boundaries", {surface(0)}}}}}}}}},
            {"vertices", {{x, 0, 0}, {x + 1000, 0, 0}, {x + 1000, 1000, 0}, {x, 1000, 0}}}};
    };
    const fs::path path = test::scratch_folder("cityjson_seq") / "two.city.jsonl";
    // A blank line before the header is no header.
    std::string lines = "\n";
    for (const json& line : {header, feature("a", 0), feature("b", 5000)}) lines += line.dump() + "\n";
    test::write_text(path, lines);
    const Model model = load_model(path.string());
    ASSERT_EQ(model.nodes[0].children.size(), 2u);
    EXPECT_EQ(model_bounds(model).size().x(), 6);
    EXPECT_EQ(model.reference_system, "");
    // The header's metadata names the reference system of every feature.
    json placed = header;
    placed["metadata"] = {{"referenceSystem", "EPSG:7415"}};
    lines = placed.dump() + "\n" + feature("a", 0).dump() + "\n";
    test::write_text(path, lines);
    EXPECT_EQ(load_model(path.string()).reference_system, "EPSG:7415");
    placed["metadata"] = {{"referenceSystem", ""}};  // not none: a file without a system leaves it out
    test::write_text(path, placed.dump() + "\n" + feature("a", 0).dump() + "\n");
    EXPECT_NE(test::input_error_of([&] {
                  load_model(path.string());
              }).find("line 1: metadata: 'referenceSystem' is empty"),
              std::string::npos);
    // An object in two features would be drawn twice; a feature's id names its main object (from a
    // hostile-input run, which saw both read without a word).
    test::write_text(path,
                     header.dump() + "\n" + feature("a", 0).dump() + "\n" + feature("a", 0).dump() + "\n");
    EXPECT_NE(test::input_error_of([&] {
                  load_model(path.string());
              }).find("line 3: CityObjects 'a' is on line 2 too: each object is in one feature"),
              std::string::npos);
    json misnamed = feature("a", 0);
    misnamed["id"] = "z";
    test::write_text(path, header.dump() + "\n" + misnamed.dump() + "\n");
    EXPECT_NE(test::input_error_of([&] {
                  load_model(path.string());
              }).find("line 2: 'id' names none of the feature's CityObjects"),
              std::string::npos);
    // Objects in the first line are refused, not dropped.
    json holding = header;
    holding["CityObjects"] = feature("c", 0)["CityObjects"];
    test::write_text(path, holding.dump() + "\n" + feature("a", 0).dump() + "\n");
    EXPECT_NE(test::input_error_of([&] { load_model(path.string()); })
                  .find("two.city.jsonl: line 1: CityObjects is not empty: a CityJSONSeq's first line holds "
                        "the metadata"),
              std::string::npos);
    holding["CityObjects"] = 5;  // not an object at all
    test::write_text(path, holding.dump() + "\n" + feature("a", 0).dump() + "\n");
    EXPECT_NE(
        test::input_error_of([&] { load_model(path.string()); }).find("line 1: CityObjects is not empty"),
        std::string::npos);
}

// FILE#OBJECT reads one object of a city file, at the whole file's origin;
// a surface without semantics is coloured as its facing suggests.
TEST(CityJsonImport, OneObjectOfADistrictAndColoursByFacing) {
    const json objects = {
        {"a", building(json::array({surface(0)}))},
        {"b",
         {{"type", "Building"},
          {"geometry",
           {{{"type", "MultiSurface"},
             {"lod", "1"},
             {"boundaries", {surface(4)}},
             {"semantics", {{"surfaces", {{{"type", "RoofSurface"}}}}, {"values", {0}}}}}}}}}};
    const json vertices = {{0, 0, 0},     {1000, 0, 0},  {1000, 1000, 0},  {0, 1000, 0},
                           {50000, 0, 0}, {51000, 0, 0}, {51000, 1000, 0}, {50000, 1000, 0}};
    const fs::path path = test::scratch_folder("cityjson_object") / "two.city.json";
    test::write_text(path, city(objects, vertices).dump());
    const Model whole = load_model(path.string()), b = load_model(path.string() + "#b");
    EXPECT_EQ(b.origin, whole.origin);
    EXPECT_EQ(b.nodes[0].name, "b");
    ASSERT_EQ(whole.nodes[2].name, "b");
    EXPECT_EQ(model_bounds(b).min, model_bounds(extract_subtree(whole, 2)).min);  // where the district has it
    EXPECT_NE(test::input_error_of([&] {
                  load_model(path.string() + "#c");
              }).find("no object named 'c' (2 objects: a, ...)"),
              std::string::npos);
    // a's square faces up without semantics: drawn in the roof colour of b's RoofSurface.
    const Model a = load_model(path.string() + "#a");
    EXPECT_EQ(a.materials[std::size_t(a.nodes[0].primitives[0].material)].base_color,
              b.materials[std::size_t(b.nodes[1].primitives[0].material)].base_color);
}

// Where the file lies on the Earth, as it names it (map_projection.h places it).
TEST(CityJsonImport, KeepsTheReferenceSystem) {
    const json one = {{"b", building(json::array({surface(0)}))}};
    json file = city(one, square_vertices);
    EXPECT_EQ(read(file, "no_system").reference_system, "");
    file["metadata"] = {{"referenceSystem", "https://www.opengis.net/def/crs/EPSG/0/7415"}};
    EXPECT_EQ(read(file, "system").reference_system, "https://www.opengis.net/def/crs/EPSG/0/7415");
    file["metadata"]["referenceSystem"] = 7415;
    EXPECT_NE(
        test::input_error_of([&] { read(file, "system_number"); }).find("'referenceSystem' is not a string"),
        std::string::npos);
}

// A polygon that triangulates to nothing (two points; three in a row) leaves no primitive
// without triangles (glTF holds none: an accessor of count 0), and a file named in Latin-1 names
// its root in UTF-8: both write a glTF that reads back.
TEST(CityJsonImport, DegeneratePolygonsAndLatin1NamesWriteAGltf) {
    const json objects = {{"a", building(json::array({surface(0)}))},
                          {"b", building(json::array({{{0, 1}}, {{0, 1, 4}}}))}};
    json vertices = square_vertices;
    vertices.push_back({2000, 0, 0});  // in a row with 0 and 1
    const Model model = read(city(objects, vertices), "caf\xe9");
    EXPECT_EQ(model.nodes[0].name, "caf\xc3\xa9.city");
    EXPECT_EQ(triangles(model), 2u);
    for (const Node& node : model.nodes)
        for (const Primitive& p : node.primitives) EXPECT_GT(p.triangle_count(), 0u) << node.name;
    const fs::path out = test::scratch_folder("cityjson_degenerate") / "out.gltf";
    save_model(model, out.string());
    EXPECT_EQ(triangles(load_model(out.string())), 2u);
}

// Bad input: one line naming the file and the place.
TEST(CityJsonImport, BadFilesAreRefusedWithTheirPlace) {
    auto error_of = [](json file, const std::string& name) {
        return test::input_error_of([&] { read(file, name); });
    };
    const json one = {
        {"b",
         {{"type", "Building"},
          {"geometry", {{{"type", "MultiSurface"}, {"lod", "1"}, {"boundaries", {{{0, 1, 2, 9}}}}}}}}}};
    EXPECT_NE(error_of(city(one, square_vertices), "bad_vertex")
                  .find("CityObjects 'b': geometry 0: vertex index 9 is outside 0..3"),
              std::string::npos);
    const json cycle = {{"a", {{"type", "Building"}, {"parents", {"b"}}}},
                        {"b", {{"type", "BuildingPart"}, {"parents", {"a"}}}}};
    EXPECT_NE(error_of(city(cycle, square_vertices), "cycle").find("parents: a cycle (a > b > a)"),
              std::string::npos);
    json no_transform = city(one, square_vertices);
    no_transform.erase("transform");
    EXPECT_NE(error_of(no_transform, "no_transform").find("missing member 'transform'"), std::string::npos);
    json textured = city({{"b",
                           {{"type", "Building"},
                            {"geometry",
                             {{{"type", "MultiSurface"},
                               {"lod", "1"},
                               {"boundaries", {surface(0)}},
                               {"texture", {{"t", {{"values", {{{5, 0, 0, 0, 0}}}}}}}}}}}}}},
                         square_vertices);
    textured["appearance"] = {{"textures", {{{"type", "PNG"}, {"image", "a.png"}}}},
                              {"vertices-texture", {{0, 0}}}};
    EXPECT_NE(error_of(textured, "bad_texture").find("texture index 5 is outside 0..0"), std::string::npos);
    textured["appearance"]["vertices-texture"] = {{0, 2e6}};  // a float holds it, no texture repeats so often
    EXPECT_NE(error_of(textured, "far_uv").find("vertices-texture 0 is not two numbers in [-1e6, 1e6]"),
              std::string::npos);
    EXPECT_NE(error_of(json::array(), "not_object").find("not a CityJSON object"), std::string::npos);
}

TEST(CityJsonImport, SharedModelsReadWithTheirHierarchy) {
    const fs::path parts = test::shared_model("cityjson/DH_01_subs.city.json"),
                   bag = test::shared_model("cityjson/3dbag_multi_lod.city.json");
    if (!fs::exists(parts) || !fs::exists(bag)) GTEST_SKIP() << "../shared/models/cityjson is absent";
    const Model with_parts = load_model(parts.string());
    EXPECT_EQ(tree_depth(with_parts), 3);  // file > Building > BuildingPart > surface
    EXPECT_EQ(with_parts.nodes[0].children.size(), 4u);
    const Model ladder = load_model(bag.string());
    EXPECT_EQ(ladder.nodes[0].children.size(), 10u);
    EXPECT_GT(triangles(ladder), triangles(load_model(bag.string(), {.chain_level = 0, .city_lod = "1.2"})));
}

}  // namespace
}  // namespace boxlod
