#include "toolkit/formats/gltf_texture_transform.h"

#include "base/input_error.h"
#include "test_support.h"
#include "toolkit/formats/model_io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace boxlod;
using json = nlohmann::json;

namespace {

// A textured quad written as a .gltf, its JSON to edit.
struct QuadFile {
    std::filesystem::path path;
    json document;

    explicit QuadFile(const std::string& name) : path(test::scratch_folder(name) / "quad.gltf") {
        Model model;
        model.source = "quad";
        add_node(model, -1, "quad");
        Primitive quad;
        quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        quad.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        quad.indices = {0, 1, 2, 0, 2, 3};
        quad.polygon_count = 1;
        quad.material = 0;
        model.nodes[0].primitives.push_back(quad);
        Material material;
        material.base_color_texture = 0;
        material.normal_texture = 1;
        model.materials.push_back(material);
        for (int t = 0; t < 2; ++t) {
            Texture texture;
            texture.image = Image8(2, 2, 4, std::uint8_t(60 * t + 50));
            model.textures.push_back(texture);
        }
        save_model(model, path.string());
        document = json::parse(test::read_text(path));
    }
    json& base() { return document["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]; }
    json& normal() { return document["materials"][0]["normalTexture"]; }
    std::vector<Eigen::Vector2f> uvs_read() {
        test::write_text(path, document.dump());
        return load_model(path.string()).nodes[0].primitives.at(0).uvs;
    }
    std::string problem() {
        return test::input_error_of([&] { uvs_read(); });
    }
};

}  // namespace

TEST(GltfTextureTransform, AMaterialsMapPlacesItsPrimitivesTextureCoordinates) {
    QuadFile file("texture_transform");
    const json transform = {{"offset", {0.5, 0.25}}, {"rotation", M_PI / 2}, {"scale", {2, 3}}};
    file.base()["extensions"]["KHR_texture_transform"] = transform;
    file.normal()["extensions"]["KHR_texture_transform"] = transform;
    file.document["extensionsUsed"] = json::array({"KHR_texture_transform"});
    // T * R * S as three.js's GLTFLoader applies it: u' = sx c u + sy s v + ox, v' = -sx s u + sy c v + oy.
    const std::vector<Eigen::Vector2f> uvs = file.uvs_read(),
                                       expected = {
                                           {0.5f, 0.25f}, {0.5f, -1.75f}, {3.5f, -1.75f}, {3.5f, 0.25f}};
    ASSERT_EQ(uvs.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_LT((uvs[i] - expected[i]).norm(), 1e-6f) << i;
    // Required, it is read too; written back, the coordinates are placed already.
    file.document["extensionsRequired"] = json::array({"KHR_texture_transform"});
    const Model read = [&] {
        file.uvs_read();
        return load_model(file.path.string());
    }();
    save_model(read, file.path.string());
    EXPECT_EQ(json::parse(test::read_text(file.path)).dump().find("KHR_texture_transform"),
              std::string::npos);
    EXPECT_EQ(load_model(file.path.string()).nodes[0].primitives[0].uvs, read.nodes[0].primitives[0].uvs);
}

TEST(GltfTextureTransform, MapsBoxlodCannotDrawAreRefused) {
    QuadFile file("texture_transform_refused");
    file.base()["extensions"]["KHR_texture_transform"] = {{"scale", {2, 2}}};
    EXPECT_NE(file.problem().find("material 0: its textures are placed by different KHR_texture_transforms"),
              std::string::npos)
        << file.problem();
    file.normal()["extensions"]["KHR_texture_transform"] = {{"scale", {2, 2}}};
    EXPECT_EQ(file.problem(), "");
    file.base()["extensions"]["KHR_texture_transform"]["scale"] = {2e6, 2};
    file.normal()["extensions"]["KHR_texture_transform"]["scale"] = {2e6, 2};
    EXPECT_NE(file.problem().find("KHR_texture_transform.scale expected a number in [-1000000, 1000000]"),
              std::string::npos)
        << file.problem();
    file.base()["extensions"]["KHR_texture_transform"] = {{"texCoord", 1}};
    file.normal()["extensions"]["KHR_texture_transform"] = {{"texCoord", 1}};
    EXPECT_NE(file.problem().find("TEXCOORD_1 (boxlod reads TEXCOORD_0 only)"), std::string::npos)
        << file.problem();
    // The extension's texCoord overrides the texture info's.
    file.base()["extensions"]["KHR_texture_transform"] = {{"texCoord", 0}};
    file.normal()["extensions"]["KHR_texture_transform"] = {{"texCoord", 0}};
    file.base()["texCoord"] = 1;
    file.normal()["texCoord"] = 1;
    EXPECT_EQ(file.problem(), "");
    file.base()["extensions"]["KHR_texture_transform"] = {{"rotation", "quarter"}};
    EXPECT_NE(file.problem().find("rotation"), std::string::npos) << file.problem();
}

TEST(GltfTextureTransform, TheTexturesOfMaterialExtensionsArePlacedAndCheckedToo) {
    QuadFile file("texture_transform_nested");
    const json transform = {{"offset", {0.5, 0}}};
    // Specular-glossiness' diffuse replaces the base colour: only its map counts beside the normal map's.
    file.document["materials"][0]["extensions"]["KHR_materials_pbrSpecularGlossiness"] = {
        {"diffuseTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}};
    file.normal()["extensions"]["KHR_texture_transform"] = transform;
    std::vector<Eigen::Vector2f> uvs = file.uvs_read();
    ASSERT_EQ(uvs.size(), 4u);
    EXPECT_EQ(uvs[1], Eigen::Vector2f(1.5f, 0));
    // An identity map is no map: it agrees with a texture without one.
    file.normal()["extensions"]["KHR_texture_transform"] = {{"offset", {0, 0}}};
    json& diffuse =
        file.document["materials"][0]["extensions"]["KHR_materials_pbrSpecularGlossiness"]["diffuseTexture"];
    diffuse.erase("extensions");
    EXPECT_EQ(file.uvs_read()[1], Eigen::Vector2f(1, 0));
    // Its coordinate set and its values are checked as a texture info's of the material's own.
    diffuse["texCoord"] = 1;
    EXPECT_NE(file.problem().find("TEXCOORD_1"), std::string::npos) << file.problem();
    diffuse.erase("texCoord");
    diffuse["extensions"]["KHR_texture_transform"] = {{"offset", 5}};
    EXPECT_NE(file.problem().find("KHR_texture_transform.offset: expected two numbers"), std::string::npos)
        << file.problem();
    diffuse["extensions"]["KHR_texture_transform"] = {{"rotation", 1e300}};
    EXPECT_NE(file.problem().find(
                  "KHR_texture_transform.rotation expected a number in [-1000000, 1000000], got '1e+300'"),
              std::string::npos)
        << file.problem();
}
