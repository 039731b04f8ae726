#include "toolkit/formats/gltf_io.h"

#include "base/input_error.h"
#include "test_support.h"
#include "toolkit/formats/gltf_extras.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/model/cost.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <Eigen/Geometry>
#include <algorithm>
#include <nlohmann/json.hpp>

using namespace boxlod;
namespace fs = std::filesystem;

namespace {

Primitive quad(float z, int material) {
    Primitive p;
    p.positions = {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}};
    p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    p.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    p.tangents = {{1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, -1}};
    p.indices = {0, 1, 2, 0, 2, 3};
    p.polygon_count = 1;  // one quad
    p.material = material;
    return p;
}

// A small building-like tree with everything the format must carry.
Model sample_model() {
    Model model;
    model.source = "sample";
    int lot = add_node(model, -1, "Lot");
    model.nodes[lot].rule = "Lot";
    Scope scope;
    scope.center = {0.5f, 0.5f, 0.1f};
    scope.axes = Eigen::AngleAxisf(0.3f, Eigen::Vector3f::UnitY()).toRotationMatrix();
    scope.half_extents = {0.5f, 0.5f, 0.1234567f};
    model.nodes[lot].scope = scope;
    int mass = add_node(model, lot, "Mass");
    model.nodes[mass].rule = "Mass";
    model.nodes[mass].primitives.push_back(quad(0, 0));
    for (int i = 0; i < 2; ++i) {
        int window = add_node(model, mass, "Window" + std::to_string(i));
        model.nodes[window].rule = "Window";
        model.nodes[window].instance_of = "window";
        model.nodes[window].primitives.push_back(quad(0.1f * float(i + 1), 1));
    }
    Material brick;
    brick.name = "brick";
    brick.base_color = {0.8f, 0.4f, 0.3f, 1};
    brick.base_color_texture = 0;
    brick.normal_texture = 1;
    brick.height_texture = 2;
    brick.height_depth = 0.375f;
    brick.specular_color = {0.1f, 0.2f, 0.3f};
    brick.shininess = 12.5f;
    brick.specular_glossiness = true;  // written back as KHR_materials_pbrSpecularGlossiness
    brick.specular_texture = 0;
    brick.alpha_mode = AlphaMode::mask;
    brick.alpha_cutoff = 0.25f;
    Material glass;
    glass.name = "glass";
    glass.double_sided = true;
    glass.alpha_mode = AlphaMode::blend;
    model.materials = {brick, glass};
    for (int t = 0; t < 3; ++t) {
        Texture texture;
        texture.name = std::vector<std::string>{"brick_color.png", "brick_normal.png", "brick_height.png"}[t];
        if (t == 2) {
            texture.image16 = Image16(3, 2, 1);
            for (std::size_t i = 0; i < 6; ++i) texture.image16.pixels[i] = std::uint16_t(i * 9001 + 3);
        } else {
            texture.image = Image8(3, 2, 4);
            for (std::size_t i = 0; i < texture.image.pixels.size(); ++i)
                texture.image.pixels[i] = std::uint8_t(i * 13 + t);
        }
        model.textures.push_back(texture);
    }
    return model;
}

// The sample model as its export writes it: what the untextured glass of the
// windows never samples is left out (toolkit/model/vertex_layout.h).
Model as_written(Model model) {
    for (int window : {2, 3}) {
        model.nodes[std::size_t(window)].primitives[0].uvs.clear();
        model.nodes[std::size_t(window)].primitives[0].tangents.clear();
    }
    return model;
}

void expect_same_model(const Model& a, const Model& b) {
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        const Node& x = a.nodes[i];
        const Node& y = b.nodes[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.rule, y.rule);
        EXPECT_EQ(x.parent, y.parent);
        EXPECT_EQ(x.children, y.children);
        EXPECT_EQ(x.instance_of, y.instance_of);
        ASSERT_EQ(x.scope.has_value(), y.scope.has_value());
        if (x.scope) {
            EXPECT_EQ(x.scope->center, y.scope->center);
            EXPECT_EQ(x.scope->axes, y.scope->axes);
            EXPECT_EQ(x.scope->half_extents, y.scope->half_extents);
        }
        ASSERT_EQ(x.primitives.size(), y.primitives.size());
        for (std::size_t p = 0; p < x.primitives.size(); ++p) {
            EXPECT_EQ(x.primitives[p].positions, y.primitives[p].positions);
            EXPECT_EQ(x.primitives[p].normals, y.primitives[p].normals);
            EXPECT_EQ(x.primitives[p].uvs, y.primitives[p].uvs);
            EXPECT_EQ(x.primitives[p].tangents, y.primitives[p].tangents);
            EXPECT_EQ(x.primitives[p].indices, y.primitives[p].indices);
            EXPECT_EQ(x.primitives[p].polygon_count, y.primitives[p].polygon_count);
            EXPECT_EQ(x.primitives[p].material, y.primitives[p].material);
        }
    }
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        EXPECT_EQ(a.materials[i].name, b.materials[i].name);
        EXPECT_EQ(a.materials[i].base_color, b.materials[i].base_color);
        EXPECT_EQ(a.materials[i].base_color_texture, b.materials[i].base_color_texture);
        EXPECT_EQ(a.materials[i].normal_texture, b.materials[i].normal_texture);
        EXPECT_EQ(a.materials[i].height_texture, b.materials[i].height_texture);
        EXPECT_EQ(a.materials[i].height_depth, b.materials[i].height_depth);
        EXPECT_EQ(a.materials[i].specular_color, b.materials[i].specular_color);
        EXPECT_EQ(a.materials[i].shininess, b.materials[i].shininess);
        EXPECT_EQ(a.materials[i].specular_glossiness, b.materials[i].specular_glossiness);
        EXPECT_EQ(a.materials[i].specular_texture, b.materials[i].specular_texture);
        EXPECT_EQ(a.materials[i].double_sided, b.materials[i].double_sided);
        EXPECT_EQ(a.materials[i].alpha_mode, b.materials[i].alpha_mode);
        EXPECT_EQ(a.materials[i].alpha_cutoff, b.materials[i].alpha_cutoff);
    }
    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (std::size_t i = 0; i < a.textures.size(); ++i) {
        EXPECT_EQ(a.textures[i].image.pixels, b.textures[i].image.pixels);
        EXPECT_EQ(a.textures[i].image16.pixels, b.textures[i].image16.pixels);
    }
    EXPECT_EQ(a.is_lod, b.is_lod);
    EXPECT_EQ(a.lod_params, b.lod_params);
}

// A glTF whose single buffer is a data URI of `bytes`.
std::string gltf_with_buffer(const std::vector<std::uint8_t>& bytes, const std::string& body) {
    return R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": )" + std::to_string(bytes.size()) +
           R"(, "uri": "data:application/octet-stream;base64,)" + test::base64(bytes) + "\"}], " + body + "}";
}

// One triangle: positions (36 bytes) then three uint16 indices.
std::vector<std::uint8_t> triangle_bytes(float x0 = 0, std::uint16_t last_index = 2) {
    std::vector<std::uint8_t> bytes;
    test::append_bytes<float>(bytes, {x0, 0, 0, 1, 0, 0, 0, 1, 0});
    test::append_bytes<std::uint16_t>(bytes, {0, 1, last_index, 0});
    return bytes;
}

const char* triangle_mesh = R"(
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}])";

std::string expect_input_error(const std::string& path, int chain_level = 0) {
    try {
        load_model(path, {.chain_level = chain_level, .city_lod = ""});
    } catch (const InputError& error) {
        std::string message = error.what();
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    }
    ADD_FAILURE() << "no InputError for " << path;
    return "";
}

}  // namespace

TEST(GltfIo, ExportThenImportGivesTheSameModel) {
    auto folder = test::scratch_folder("gltf_round_trip");
    Model model = sample_model();
    for (const char* name : {"house.gltf", "house.glb"}) {
        std::string path = (folder / name).string();
        save_model(model, path);
        expect_same_model(as_written(model), load_model(path));
    }
    EXPECT_TRUE(fs::exists(folder / "house.bin"));
    EXPECT_TRUE(fs::exists(folder / "brick_color.png"));
    EXPECT_TRUE(fs::exists(folder / "brick_normal.png"));
}

// What an engine reads: 16-bit indices where they fit, attributes only where the
// material samples them, the specular-glossiness extension declared.
TEST(GltfIo, IndicesAttributesAndExtensionsAsAClientReadsThem) {
    auto folder = test::scratch_folder("gltf_client_view");
    Model model = sample_model();
    Primitive& big =
        model.nodes[1].primitives.emplace_back(quad(0.5f, 0));  // 70,000 vertices: 32-bit indices
    big.positions.resize(70000, Eigen::Vector3f(0.5f, 0.5f, 0.5f));
    big.normals.resize(70000, Eigen::Vector3f::UnitZ());
    big.uvs.resize(70000, Eigen::Vector2f::Zero());
    big.tangents.resize(70000, Eigen::Vector4f(1, 0, 0, 1));
    big.indices.insert(big.indices.end(), {69999, 0, 1});
    big.polygon_count = 2;
    save_model(model, (folder / "house.glb").string());
    tinygltf::Model gltf;
    std::string error, warning;
    ASSERT_TRUE(
        tinygltf::TinyGLTF().LoadBinaryFromFile(&gltf, &error, &warning, (folder / "house.glb").string()))
        << error;
    std::vector<int> index_types;
    for (const tinygltf::Mesh& mesh : gltf.meshes)
        for (const tinygltf::Primitive& p : mesh.primitives) {
            index_types.push_back(gltf.accessors[std::size_t(p.indices)].componentType);
            const bool textured =
                gltf.materials[std::size_t(p.material)].pbrMetallicRoughness.baseColorTexture.index >= 0;
            EXPECT_EQ(p.attributes.count("TEXCOORD_0"), textured ? 1u : 0u);
            EXPECT_EQ(p.attributes.count("TANGENT"),
                      textured ? 1u : 0u);  // the brick has a normal map, the glass nothing
        }
    EXPECT_EQ(
        index_types,
        (std::vector<int>{TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}));
    EXPECT_EQ(gltf.extensionsUsed, std::vector<std::string>{"KHR_materials_pbrSpecularGlossiness"});
    const tinygltf::Value& sg = gltf.materials[0].extensions.at("KHR_materials_pbrSpecularGlossiness");
    EXPECT_FLOAT_EQ(float(sg.Get("specularFactor").Get(2).GetNumberAsDouble()), 0.3f);
    EXPECT_FLOAT_EQ(float(sg.Get("diffuseFactor").Get(0).GetNumberAsDouble()), 0.8f);
    EXPECT_EQ(sg.Get("specularGlossinessTexture").Get("index").GetNumberAsInt(), 0);
    EXPECT_EQ(gltf.materials[1].extensions.count("KHR_materials_pbrSpecularGlossiness"),
              0u);  // the glass states no specular
    expect_same_model(as_written(model), load_model((folder / "house.glb").string()));
}

// A primitive without texture coordinates draws its material untextured
// (the renderer) and is written so: a glTF texture needs them (the validator's
// MESH_PRIMITIVE_TOO_FEW_TEXCOORDS on LightWave files whose textures are
// mapped by projection). A material drawn both ways is written both ways.
TEST(GltfIo, APrimitiveWithoutTextureCoordinatesIsWrittenUntextured) {
    auto folder = test::scratch_folder("gltf_untextured");
    Model model = sample_model();
    const int brick = model.nodes[1].primitives[0].material;
    ASSERT_TRUE(samples_textures(model.materials[std::size_t(brick)]));
    Primitive bare = model.nodes[1].primitives[0];
    bare.uvs.clear();
    bare.tangents.clear();
    model.nodes[1].primitives.push_back(bare);
    save_model(model, (folder / "both.glb").string());
    tinygltf::Model gltf;
    std::string error, warning;
    ASSERT_TRUE(
        tinygltf::TinyGLTF().LoadBinaryFromFile(&gltf, &error, &warning, (folder / "both.glb").string()))
        << error;
    int textured = 0, untextured = 0;
    for (const tinygltf::Mesh& mesh : gltf.meshes)
        for (const tinygltf::Primitive& p : mesh.primitives) {
            const tinygltf::Material& material = gltf.materials[std::size_t(p.material)];
            if (material.name != model.materials[std::size_t(brick)].name) continue;
            const bool sampled = material.pbrMetallicRoughness.baseColorTexture.index >= 0 ||
                                 material.normalTexture.index >= 0;
            EXPECT_EQ(sampled, p.attributes.count("TEXCOORD_0") == 1);
            ++(sampled ? textured : untextured);
        }
    EXPECT_EQ(textured, 1);
    EXPECT_EQ(untextured, 1);
    // Drawn only without them, the material is written once, untextured, and
    // the textures only it samples not at all (the validator's UNUSED_OBJECT).
    model.nodes[1].primitives.erase(model.nodes[1].primitives.begin());
    save_model(model, (folder / "bare.glb").string());
    const Model back = load_model((folder / "bare.glb").string());
    const auto written = std::find_if(back.materials.begin(), back.materials.end(), [&](const Material& m) {
        return m.name == model.materials[std::size_t(brick)].name;
    });
    ASSERT_NE(written, back.materials.end());
    EXPECT_FALSE(samples_textures(*written));
    EXPECT_TRUE(back.textures.empty());
}

// A node with nothing to write (an unnamed, empty OBJ group in assimp's
// regr01.obj) came out as null, which no reader takes: it is named instead.
TEST(GltfIo, AnEmptyUnnamedNodeIsWrittenAsAnObject) {
    auto folder = test::scratch_folder("gltf_empty_node");
    Model model = sample_model();
    add_node(model, 0, "");
    save_model(model, (folder / "m.gltf").string());
    const nlohmann::json gltf = nlohmann::json::parse(test::read_text(folder / "m.gltf"));
    for (const nlohmann::json& node : gltf.at("nodes")) EXPECT_TRUE(node.is_object()) << node.dump();
    EXPECT_EQ(gltf.at("nodes").back().value("name", ""), "node " + std::to_string(model.nodes.size() - 1));
    EXPECT_EQ(load_model((folder / "m.gltf").string()).nodes.size(), model.nodes.size());
}

namespace {

// A one-triangle glTF at `path` whose material states `extension` with `fields` (JSON).
std::string extension_file(const fs::path& path, const std::string& extension, const std::string& fields) {
    std::string body = std::string(triangle_mesh) + R"(, "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}],
      "extensionsUsed": [")" +
                       extension + R"("], "materials": [{"extensions": {")" + extension + "\": " + fields +
                       "}}]";
    body.replace(body.find(R"("indices": 1)"), 12, R"("indices": 1, "material": 0)");
    test::write_text(path, gltf_with_buffer(triangle_bytes(), body));
    return path.string();
}

}  // namespace

// A file from another tool: its specular-glossiness material is what boxlod
// renders (diffuse as base colour) and what convert writes back.
TEST(GltfIo, SpecularGlossinessFromAnotherToolIsReadAndKept) {
    auto folder = test::scratch_folder("gltf_specular_glossiness");
    auto file = [&](const std::string& name, const std::string& fields) {
        return extension_file(folder / name, "KHR_materials_pbrSpecularGlossiness", fields);
    };
    Model model = load_model(
        file("sg.gltf", R"({"diffuseFactor": [0.5, 0.25, 1, 1], "specularFactor": [0.75, 0.5, 0.25],
                                               "glossinessFactor": 0.5})"));
    const Material& m = model.materials[0];
    EXPECT_TRUE(m.specular_glossiness);
    EXPECT_EQ(m.base_color, Eigen::Vector4f(0.5f, 0.25f, 1, 1));
    EXPECT_EQ(m.specular_color, Eigen::Vector3f(0.75f, 0.5f, 0.25f));
    EXPECT_FLOAT_EQ(m.shininess, 30);  // roughness 0.5, alpha 0.25: 2 / 0.25^2 - 2
    EXPECT_EQ(m.glossiness, 0.5f);
    save_model(model, (folder / "converted.gltf").string());
    const Material back = load_model((folder / "converted.gltf").string()).materials[0];
    EXPECT_TRUE(back.specular_glossiness);
    EXPECT_EQ(back.base_color, m.base_color);
    EXPECT_EQ(back.specular_color, m.specular_color);
    EXPECT_EQ(back.shininess, m.shininess);
    EXPECT_NE(test::read_text(folder / "converted.gltf").find(R"("glossinessFactor":0.5)"),
              std::string::npos);
    // A mirror's glossiness 1 is beyond the largest exponent boxlod draws, and written back as it was.
    Model mirror = load_model(file("mirror.gltf", R"({"glossinessFactor": 1})"));
    EXPECT_FLOAT_EQ(mirror.materials[0].shininess, float(shininess_range.max));
    save_model(mirror, (folder / "mirror_converted.gltf").string());
    EXPECT_NE(test::read_text(folder / "mirror_converted.gltf").find(R"("glossinessFactor":1.0)"),
              std::string::npos);
    // Every factor has the extension's range.
    EXPECT_NE(expect_input_error(file("gloss.gltf", R"({"glossinessFactor": 2})")).find("glossinessFactor"),
              std::string::npos);
    EXPECT_NE(
        expect_input_error(file("spec.gltf", R"({"specularFactor": [0, -1, 0]})")).find("specularFactor"),
        std::string::npos);
    expect_input_error(file("diffuse.gltf", R"({"diffuseFactor": [1, 1]})"));
    expect_input_error(file("texture.gltf", R"({"diffuseTexture": {"index": 4}})"));
    expect_input_error(file("form.gltf", R"({"specularGlossinessTexture": {"texCoord": 0}})"));
}

// KHR_materials_specular (a metallic-roughness material's specular strength and
// colour) is kept as read and written back, its textures with the model's.
TEST(GltfIo, KhrMaterialsSpecularIsKeptAndWrittenBack) {
    auto folder = test::scratch_folder("gltf_khr_specular");
    auto file = [&](const std::string& name, const std::string& fields) {
        return extension_file(folder / name, "KHR_materials_specular", fields);
    };
    Model model =
        load_model(file("specular.gltf", R"({"specularFactor": 0.25, "specularColorFactor": [2, 0.5, 1]})"));
    ASSERT_TRUE(model.materials[0].specular_extension);
    const SpecularExtension read = *model.materials[0].specular_extension;
    EXPECT_EQ(read.factor, 0.25f);
    EXPECT_EQ(read.color_factor, Eigen::Vector3f(2, 0.5f, 1));  // above 1 is allowed: it scales F0
    EXPECT_EQ(read.texture, -1);
    EXPECT_FALSE(model.materials[0].specular_glossiness);
    // Written back with the model's textures, which a subtree copy renumbers.
    model.textures.push_back({"strength.png", Image8(2, 2, 4, 200), {}});
    model.textures.push_back({"tint.png", Image8(2, 2, 4, 100), {}});
    model.materials[0].specular_extension->texture = 0;
    model.materials[0].specular_extension->color_texture = 1;
    for (Node& node :
         model.nodes)  // texture coordinates, without which a primitive draws no texture (and is written so)
        for (Primitive& primitive : node.primitives)
            primitive.uvs.assign(primitive.positions.size(), Eigen::Vector2f(0.5f, 0.5f));
    save_model(model, (folder / "converted.glb").string());
    Model back = load_model((folder / "converted.glb").string());
    ASSERT_TRUE(back.materials[0].specular_extension);
    const SpecularExtension& again = *back.materials[0].specular_extension;
    EXPECT_EQ(again.factor, read.factor);
    EXPECT_EQ(again.color_factor, read.color_factor);
    ASSERT_GE(again.texture, 0);
    ASSERT_GE(again.color_texture, 0);
    EXPECT_EQ(back.textures[std::size_t(again.texture)].image.pixels, model.textures[0].image.pixels);
    EXPECT_EQ(back.textures[std::size_t(again.color_texture)].image.pixels, model.textures[1].image.pixels);
    EXPECT_GT(model_cost(back).texture_bytes, 0u);  // its textures are paid for
    // Every factor has a range; textures must exist.
    EXPECT_NE(expect_input_error(file("factor.gltf", R"({"specularFactor": 1.5})")).find("specularFactor"),
              std::string::npos);
    EXPECT_NE(expect_input_error(file("colour.gltf", R"({"specularColorFactor": [0, -1, 0]})"))
                  .find("specularColorFactor"),
              std::string::npos);
    expect_input_error(file("huge.gltf", R"({"specularColorFactor": [1e30, 1, 1]})"));
    expect_input_error(file("texture.gltf", R"({"specularTexture": {"index": 4}})"));
    expect_input_error(file("form.gltf", R"({"specularColorTexture": {"texCoord": 0}})"));
}

TEST(GltfIo, GlossinessAndShininessConvertBothWays) {
    for (float g : {0.0f, 0.25f, 0.5f, 0.75f, 0.85f})
        EXPECT_NEAR(glossiness_of_shininess(shininess_of_glossiness(g)), g, 1e-5f);
    EXPECT_FLOAT_EQ(shininess_of_glossiness(0), 0);
    EXPECT_FLOAT_EQ(shininess_of_glossiness(1),
                    float(shininess_range.max));  // a mirror: the largest exponent allowed
}

TEST(GltfIo, LodMarkAndParametersSurviveTheRoundTrip) {
    auto folder = test::scratch_folder("gltf_lod_mark");
    Model model = sample_model();
    model.is_lod = true;
    model.lod_params = {{"current_level", "2"}, {"level_mode", "top-down"}};
    save_model(model, (folder / "lod.gltf").string());
    Model back = load_model((folder / "lod.gltf").string());
    EXPECT_TRUE(back.is_lod);
    EXPECT_EQ(back.lod_params, model.lod_params);
}

// A chain of levels in one file (MSFT_lod): level 0 alone in the scene, so a
// reader without the extension (boxlod too) gets the finest level; what the
// coarser level has equal to level 0 (textures, materials, meshes) is stored once.
TEST(GltfIo, LevelsInOneFileWithMsftLod) {
    auto folder = test::scratch_folder("gltf_lods");
    Model finest = sample_model(), coarse = sample_model();
    coarse.nodes.resize(2);  // the lot and its mass, without windows
    coarse.nodes[1].children.clear();
    coarse.materials[1].name = "glass_coarse";
    for (const char* name : {"chain.glb", "chain.gltf"}) {
        std::string path = (folder / name).string();
        export_gltf_lods({&finest, &coarse}, {LodSwitch{40, 0.25, 0, 0}}, path, 2);
        Model read_back = load_model(path);  // (materials and textures: every level's)
        read_back.materials.resize(finest.materials.size());
        read_back.textures.resize(finest.textures.size());
        expect_same_model(as_written(finest), read_back);
        // Level 1 on request (render --level), as an MSFT_lod client draws it; past the last, refused.
        Model level_1 = load_model(path, {.chain_level = 1, .city_lod = ""});
        ASSERT_EQ(level_1.nodes.size(), coarse.nodes.size());
        EXPECT_EQ(level_1.nodes[1].primitives.at(0).positions, coarse.nodes[1].primitives.at(0).positions);
        EXPECT_EQ(level_1.materials[std::size_t(level_1.nodes[1].primitives[0].material)].name,
                  coarse.materials[std::size_t(coarse.nodes[1].primitives[0].material)].name);
        EXPECT_NE(expect_input_error(path, 2).find("the chain has levels 0..1"), std::string::npos);
        tinygltf::Model gltf;
        std::string error, warning;
        tinygltf::TinyGLTF reader;
        bool read = std::string(name).ends_with(".glb")
                        ? reader.LoadBinaryFromFile(&gltf, &error, &warning, path)
                        : reader.LoadASCIIFromFile(&gltf, &error, &warning, path);
        ASSERT_TRUE(read) << error;
        ASSERT_EQ(gltf.scenes.at(0).nodes, std::vector<int>{0});
        const int coarse_root = int(finest.nodes.size());
        EXPECT_EQ(gltf.nodes.size(), finest.nodes.size() + 2);
        const tinygltf::Value& lod = gltf.nodes[0].extensions.at("MSFT_lod");
        ASSERT_EQ(lod.Get("ids").ArrayLen(), 1u);
        EXPECT_EQ(lod.Get("ids").Get(0).GetNumberAsInt(), coarse_root);
        EXPECT_EQ(gltf.nodes[0].extras.Get("MSFT_screencoverage").Get(0).GetNumberAsDouble(), 0.25);
        EXPECT_EQ(gltf.nodes[0].extras.Get("MSFT_screencoverage").Get(1).GetNumberAsDouble(), 0);
        EXPECT_EQ(gltf.nodes[0].extras.Get("boxlod").Get("switch_distances").Get(0).GetNumberAsDouble(), 40);
        EXPECT_EQ(gltf.extensionsUsed,
                  (std::vector<std::string>{"KHR_materials_pbrSpecularGlossiness", "MSFT_lod"}));
        EXPECT_EQ(gltf.images.size(), finest.textures.size());
        // Equal materials and geometry are shared too: the coarse mass draws level 0's mass, brick and all;
        // only the renamed glass is new.
        ASSERT_EQ(gltf.materials.size(), 3u);
        EXPECT_EQ(gltf.materials[2].name, "glass_coarse");
        EXPECT_EQ(gltf.materials[2].pbrMetallicRoughness.baseColorTexture.index, -1);
        // Level 0's mass and two windows, and the coarse level's own mesh of the mass (Babylon.js disposes
        // a replaced level's meshes) on the same accessors.
        ASSERT_EQ(gltf.meshes.size(), 4u);
        const tinygltf::Mesh &mass = gltf.meshes[std::size_t(gltf.nodes[1].mesh)],
                             &coarse_mass =
                                 gltf.meshes[std::size_t(gltf.nodes[std::size_t(coarse_root) + 1].mesh)];
        EXPECT_NE(&mass, &coarse_mass);
        EXPECT_EQ(coarse_mass.primitives[0].attributes, mass.primitives[0].attributes);
        // Level 0 (not the coarsest, which Babylon.js loads first) keeps one index list in a buffer of its
        // own, a data URI even in a .glb, so that a client that defers URIs loads the levels in order.
        ASSERT_EQ(gltf.buffers.size(), 2u);
        int deferred = 0;
        for (const tinygltf::Accessor& accessor : gltf.accessors)
            deferred +=
                accessor.bufferView >= 0 && gltf.bufferViews[std::size_t(accessor.bufferView)].buffer == 1;
        EXPECT_EQ(deferred, 1);
    }
    EXPECT_THROW(export_gltf_lods({&finest, &coarse}, {}, (folder / "bad.glb").string()), std::logic_error);
    save_model(finest, (folder / "one_level.glb").string());
    EXPECT_NE(expect_input_error((folder / "one_level.glb").string(), 1).find("not an LoD chain"),
              std::string::npos);
}

TEST(GltfIo, ExportIsByteIdenticalEveryTime) {
    auto folder = test::scratch_folder("gltf_deterministic");
    Model model = sample_model();
    save_model(model, (folder / "a.glb").string());
    save_model(model, (folder / "b.glb").string());
    EXPECT_EQ(test::read_text(folder / "a.glb"), test::read_text(folder / "b.glb"));
}

// A primitive that makes no triangle (a strip of two vertices, points) is left out: glTF holds no
// accessor of count 0, so boxlod could not write it back.
TEST(GltfIo, APrimitiveWithoutATriangleIsLeftOut) {
    auto folder = test::scratch_folder("gltf_no_triangle");
    auto replace = [](std::string& text, const std::string& from, const std::string& to) {
        text.replace(text.find(from), from.size(), to);
    };
    std::string mesh = triangle_mesh;
    replace(mesh, R"("indices": 1}]}])", R"("indices": 1}, {"attributes": {"POSITION": 2}, "mode": 5},
                                          {"attributes": {"POSITION": 0}, "mode": 0}]}])");
    replace(mesh, R"("type": "SCALAR"}])",
            R"("type": "SCALAR"}, {"bufferView": 0, "componentType": 5126, "count": 2, "type": "VEC3"}])");
    test::write_text(folder / "m.gltf", gltf_with_buffer(triangle_bytes(), mesh + R"(,
      "nodes": [{"name": "n", "mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0)"));
    const Model model = load_model((folder / "m.gltf").string());
    ASSERT_EQ(model.nodes.size(), 1u);
    EXPECT_EQ(model.nodes[0].primitives.size(), 1u);
    save_model(model, (folder / "out.glb").string());
    EXPECT_EQ(load_model((folder / "out.glb").string()).nodes[0].primitives.size(), 1u);
}

TEST(GltfIo, TransformsAreAppliedAndSharedMeshesExpanded) {
    auto folder = test::scratch_folder("gltf_transforms");
    // root translates by +10 x; child a scales by 2; child b mirrors x (matrix), which must flip the winding.
    std::string json = gltf_with_buffer(triangle_bytes(), std::string(triangle_mesh) + R"(,
      "nodes": [{"name": "root", "translation": [10, 0, 0], "children": [1, 2]},
                {"name": "a", "mesh": 0, "scale": [2, 2, 2]},
                {"name": "b", "mesh": 0, "matrix": [-1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,5,1]}],
      "scenes": [{"nodes": [0]}], "scene": 0)");
    test::write_text(folder / "t.gltf", json);
    Model model = load_model((folder / "t.gltf").string());
    ASSERT_EQ(model.nodes.size(), 3u);
    const Primitive& a = model.nodes[1].primitives.at(0);
    EXPECT_EQ(a.positions[1], Eigen::Vector3f(12, 0, 0));
    EXPECT_EQ(a.positions[2], Eigen::Vector3f(10, 2, 0));
    EXPECT_EQ(a.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    const Primitive& b = model.nodes[2].primitives.at(0);
    EXPECT_EQ(b.positions[1], Eigen::Vector3f(9, 0, 5));
    EXPECT_EQ(b.indices, (std::vector<std::uint32_t>{0, 2, 1}));
    EXPECT_EQ(model.nodes[1].instance_of, "tri");
    EXPECT_EQ(model.nodes[2].instance_of, "tri");
    EXPECT_EQ(a.polygon_count, 1u);
    EXPECT_TRUE(model.origin.isZero());  // 10 m from the file's origin: no local one
}

// A triangle placed 5,000 km out, as georeferenced exports place a building: read relative to
// the middle of its bounds in whole metres, so float keeps its millimetres (at 4e6 m a float
// steps by 0.25 m), and written back with that origin on the root.
TEST(GltfIo, AModelFarFromItsFilesOriginIsReadRelativeToALocalOne) {
    auto folder = test::scratch_folder("gltf_far");
    const std::string nodes = R"(, "nodes": [{"translation": [4000000.3, 100, -3000000.2], "children": [1]},
                {"mesh": 0, "translation": [0.001, 0, 0]}], "scenes": [{"nodes": [0]}])";
    test::write_text(folder / "far.gltf", gltf_with_buffer(triangle_bytes(), triangle_mesh + nodes));
    Model model = load_model((folder / "far.gltf").string());
    EXPECT_EQ(model.origin, Eigen::Vector3d(4000001, 101, -3000000));  // the middle, 4000000.801, 100.5, ...
    const Primitive& triangle = model.nodes.at(1).primitives.at(0);
    EXPECT_TRUE(triangle.positions[0].isApprox(Eigen::Vector3f(-0.699f, -1, -0.2f), 1e-6f));
    EXPECT_TRUE(triangle.positions[1].isApprox(Eigen::Vector3f(0.301f, -1, -0.2f), 1e-6f));
    save_model(model, (folder / "back.glb").string());
    const Model back = load_model((folder / "back.glb").string());
    EXPECT_EQ(back.origin, model.origin);
    EXPECT_EQ(back.nodes.at(1).primitives.at(0).positions, triangle.positions);

    const std::string beyond =
        R"(, "nodes": [{"mesh": 0, "translation": [2e9, 0, 0]}], "scenes": [{"nodes": [0]}])";
    test::write_text(folder / "beyond.gltf", gltf_with_buffer(triangle_bytes(), triangle_mesh + beyond));
    const std::string message = expect_input_error((folder / "beyond.gltf").string());
    EXPECT_NE(
        message.find(": scene: its middle lies at (2000000000.5, 0.5, 0), outside [-1000000000, 1000000000]"),
        std::string::npos)
        << message;
}

TEST(GltfIo, SeveralRootNodesGetOneRootNamedAfterTheFile) {
    auto folder = test::scratch_folder("gltf_roots");
    std::string json = gltf_with_buffer(triangle_bytes(), std::string(triangle_mesh) + R"(,
      "nodes": [{"name": "a", "mesh": 0}, {"name": "b", "mesh": 0}], "scenes": [{"nodes": [0, 1]}])");
    test::write_text(folder / "street.gltf", json);
    Model model = load_model((folder / "street.gltf").string());
    ASSERT_EQ(model.nodes.size(), 3u);
    EXPECT_EQ(model.nodes[0].name, "street");
    EXPECT_EQ(model.nodes[0].children, (std::vector<int>{1, 2}));
    // A file named in Latin-1 names the root in UTF-8, as glTF's JSON must.
    test::write_text(folder /
                         "stra\xdf"
                         "e.gltf",
                     json);
    Model latin1 = load_model((folder / "stra\xdf"
                                        "e.gltf")
                                  .string());
    EXPECT_EQ(latin1.nodes[0].name,
              "stra\xc3\x9f"
              "e");
    save_model(latin1, (folder / "out.glb").string());
    EXPECT_EQ(load_model((folder / "out.glb").string()).nodes[0].name,
              "stra\xc3\x9f"
              "e");
}

TEST(GltfIo, SixteenBitGreyUsedAsColourReadsAsGreyNotRed) {
    auto folder = test::scratch_folder("gltf_grey16");
    Model model = sample_model();
    model.materials[0].base_color_texture = 2;  // the 16-bit height map, now also the colour
    save_model(model, (folder / "grey.gltf").string());
    Model back = load_model((folder / "grey.gltf").string());
    const Texture& grey = back.textures[2];
    ASSERT_TRUE(grey.image16.empty());
    ASSERT_EQ(grey.image.channels, 4);
    for (std::size_t i = 0; i < 6; ++i) {
        std::uint8_t expected = std::uint8_t(model.textures[2].image16.pixels[i] >> 8);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(grey.image.pixels[i * 4 + c], expected) << i;
        EXPECT_EQ(grey.image.pixels[i * 4 + 3], 255);
    }
    // Used only as a height map, it keeps its 16 bits (ExportThenImportGivesTheSameModel).
}

// Saving beside the model must not re-encode the images it was read with:
// here the 16-bit grey image, read as 8-bit colour, would lose its low bits.
TEST(GltfIo, AnExportBesideTheModelKeepsItsImageFiles) {
    auto folder = test::scratch_folder("gltf_keeps_images");
    Model model = sample_model();
    model.materials[0].base_color_texture = 2;
    save_model(model, (folder / "house.gltf").string());
    const std::vector<std::string> images = {"brick_color.png", "brick_normal.png", "brick_height.png"};
    std::vector<std::string> before;
    for (const std::string& image : images) before.push_back(test::read_text(folder / image));
    const Model read = load_model((folder / "house.gltf").string());
    ASSERT_EQ(read.read_files.size(), 4u);  // the images, then the buffer
    EXPECT_EQ(read.read_files[2], (folder / "brick_height.png").string());
    EXPECT_EQ(read.read_files[3], (folder / "house.bin").string());
    // Through a link to the folder, by a relative path.
    fs::create_directory_symlink(folder, folder / "link");
    save_model(read, fs::relative(folder / "link" / "copy.gltf").string());
    for (std::size_t i = 0; i < images.size(); ++i)
        EXPECT_EQ(test::read_text(folder / images[i]), before[i]) << images[i];
    const nlohmann::json copy = nlohmann::json::parse(test::read_text(folder / "copy.gltf"));
    ASSERT_EQ(copy["images"].size(), 3u);
    for (const nlohmann::json& image : copy["images"]) {
        const std::string uri = image["uri"];
        EXPECT_EQ(uri.rfind("copy_texture_", 0), 0u) << uri;
        EXPECT_TRUE(fs::exists(folder / uri)) << uri;
    }
    expect_same_model(load_model((folder / "copy.gltf").string()), read);
    // A name a URI must escape reads back (the .bin's and the images' uris are encoded).
    save_model(read, (folder / "my house%41.gltf").string());
    expect_same_model(load_model((folder / "my house%41.gltf").string()), read);
    // An object of the file keeps the images of the others: b.png, read as sub/a.png, is not written over
    // a.png.
    Model two;
    add_node(two, -1, "city");
    for (int k = 0; k < 2; ++k) {
        add_node(two, 0, k ? "B" : "A");
        two.nodes[std::size_t(k + 1)].primitives.push_back(quad(0, k));
        two.materials.push_back(model.materials[1]);
        two.materials[std::size_t(k)].base_color_texture = k;
        two.textures.push_back(model.textures[std::size_t(k)]);
        two.textures[std::size_t(k)].name = k ? "b.png" : "a.png";
    }
    save_model(two, (folder / "two.gltf").string());
    fs::create_directory(folder / "sub");
    fs::rename(folder / "b.png", folder / "sub" / "a.png");
    test::write_text(folder / "two.gltf", test::replaced_once(test::read_text(folder / "two.gltf"),
                                                              "\"uri\":\"b.png\"", "\"uri\":\"sub/a.png\""));
    const std::string a_png = test::read_text(folder / "a.png");
    save_model(load_model((folder / "two.gltf#B").string()), (folder / "b_only.gltf").string());
    EXPECT_EQ(test::read_text(folder / "a.png"), a_png);
    EXPECT_TRUE(fs::exists(folder / "b_only_texture_0.png"));
    // Elsewhere the images keep their names.
    fs::create_directories(folder / "elsewhere");
    save_model(read, (folder / "elsewhere" / "copy.gltf").string());
    EXPECT_TRUE(fs::exists(folder / "elsewhere" / "brick_height.png"));
}

TEST(GltfIo, AnExportBesideTheModelKeepsItsBufferFile) {
    auto folder = test::scratch_folder("gltf_keeps_buffer");
    save_model(sample_model(), (folder / "house.gltf").string());
    fs::rename(folder / "house.gltf", folder / "a.gltf");  // a.gltf's buffer is house.bin
    const std::string bin = test::read_text(folder / "house.bin");
    const Model read = load_model((folder / "a.gltf").string());
    save_model(read, (folder / "house.gltf").string());
    EXPECT_EQ(test::read_text(folder / "house.bin"), bin);
    const nlohmann::json written = nlohmann::json::parse(test::read_text(folder / "house.gltf"));
    EXPECT_EQ(written["buffers"][0]["uri"], "house_2.bin");
    expect_same_model(load_model((folder / "house.gltf").string()), read);
    expect_same_model(load_model((folder / "a.gltf").string()), read);
}

TEST(GltfIo, BadInputGivesOneLineNamingTheFile) {
    auto folder = test::scratch_folder("gltf_bad_input");
    auto write = [&](const std::string& name, const std::string& text) {
        test::write_text(folder / name, text);
        return (folder / name).string();
    };
    EXPECT_NE(expect_input_error((folder / "missing.gltf").string()).find("no such file"), std::string::npos);
    expect_input_error(write("malformed.gltf", "{ \"asset\": {\"version\": \"2.0\"}, \"nodes\": [ "));
    expect_input_error(write("empty.gltf", R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": []}]})"));
    std::string no_geometry =
        R"({"asset": {"version": "2.0"}, "nodes": [{"name": "a"}], "scenes": [{"nodes": [0]}]})";
    EXPECT_NE(expect_input_error(write("no_geometry.gltf", no_geometry)).find("empty"), std::string::npos);

    std::string nodes = R"(, "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}])";
    auto nan_bytes = triangle_bytes(std::nanf(""));
    EXPECT_NE(
        expect_input_error(write("nan.gltf", gltf_with_buffer(nan_bytes, triangle_mesh + nodes))).find("NaN"),
        std::string::npos);
    auto inf_bytes = triangle_bytes(std::numeric_limits<float>::infinity());
    expect_input_error(write("inf.gltf", gltf_with_buffer(inf_bytes, triangle_mesh + nodes)));
    auto bad_index = triangle_bytes(0, 7);
    EXPECT_NE(expect_input_error(write("index.gltf", gltf_with_buffer(bad_index, triangle_mesh + nodes)))
                  .find("out of range"),
              std::string::npos);
    auto short_buffer = triangle_bytes();
    short_buffer.resize(30);
    expect_input_error(write("short.gltf", gltf_with_buffer(short_buffer, triangle_mesh + nodes)));
    std::string cycle =
        R"(, "nodes": [{"mesh": 0, "children": [1]}, {"children": [0]}], "scenes": [{"nodes": [0]}])";
    EXPECT_NE(
        expect_input_error(write("cycle.gltf", gltf_with_buffer(triangle_bytes(), triangle_mesh + cycle)))
            .find("twice"),
        std::string::npos);
    std::string bad_child = R"(, "nodes": [{"mesh": 0, "children": [9]}], "scenes": [{"nodes": [0]}])";
    expect_input_error(write("child.gltf", gltf_with_buffer(triangle_bytes(), triangle_mesh + bad_child)));
    const std::string projective =
        R"(, "nodes": [{"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,0]}], "scenes": [{"nodes": [0]}])";
    EXPECT_NE(expect_input_error(
                  write("matrix.gltf", gltf_with_buffer(triangle_bytes(), triangle_mesh + projective)))
                  .find("node 0: matrix is not affine"),
              std::string::npos);
    const std::string wrap = R"(, "samplers": [{"wrapS": 12345}])";
    EXPECT_NE(expect_input_error(
                  write("wrap.gltf", gltf_with_buffer(triangle_bytes(), triangle_mesh + nodes + wrap)))
                  .find("sampler 0: wrap mode 12345 is not 33071, 33648 or 10497"),
              std::string::npos);

    // A truncated .glb: the first half of a valid one.
    save_model(sample_model(), (folder / "whole.glb").string());
    std::string whole = test::read_text(folder / "whole.glb");
    expect_input_error(write("truncated.glb", whole.substr(0, whole.size() / 2)));
    expect_input_error(write("garbage.glb", "this is not a glb file at all"));
    std::string far_offset = R"(
  "bufferViews": [{"buffer": 0, "byteOffset": 18446744073709551600, "byteLength": 36}, {"buffer": 0, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}])";
    EXPECT_NE(expect_input_error(write("offset.gltf", gltf_with_buffer(triangle_bytes(), far_offset + nodes)))
                  .find("runs past"),
              std::string::npos);
    std::string huge_count = triangle_mesh;
    huge_count.replace(huge_count.find(R"("count": 3, "type": "VEC3")"), 10,
                       R"("count": 4611686018427387904)");
    EXPECT_NE(expect_input_error(write("count.gltf", gltf_with_buffer(triangle_bytes(), huge_count + nodes)))
                  .find("larger than any buffer"),
              std::string::npos);
    std::string broken_image = R"(, "images": [{"uri": "broken.png"}], "textures": [{"source": 0}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])";
    test::write_text(folder / "broken.png", "\x89PNG but not really");
    // The broken file is the image, and the message names it.
    write("image.gltf", gltf_with_buffer(triangle_bytes(), triangle_mesh + nodes + broken_image));
    try {
        load_model((folder / "image.gltf").string());
        ADD_FAILURE() << "no error for a broken texture";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  (folder / "broken.png").string() + ": cannot decode image: unknown image type");
    }
    EXPECT_NE(expect_input_error(write("model.xyz", "?")).find("unknown model format"), std::string::npos);
}
