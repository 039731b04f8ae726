#include "toolkit/formats/gltf_json.h"

#include "test_support.h"
#include "toolkit/boxlod.h"
#include "toolkit/formats/gltf_document.h"
#include "toolkit/formats/model_io.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstring>
#include <sstream>

using namespace boxlod;

namespace {

// The document with its nodes' extras as tinygltf reads them from their
// text (its writer takes them so only).
tinygltf::Model with_extras_values(tinygltf::Model document) {
    std::string json = R"({"asset":{"version":"2.0"},"nodes":[)";
    for (const tinygltf::Node& node : document.nodes)
        json += (&node == &document.nodes[0] ? "{" : ",{") +
                (node.extras_json_string.empty() ? "" : "\"extras\":" + node.extras_json_string) + "}";
    json += "]}";
    tinygltf::Model read;
    std::string error, warning;
    EXPECT_TRUE(tinygltf::TinyGLTF().LoadASCIIFromString(&read, &error, &warning, json.c_str(),
                                                         unsigned(json.size()), ""))
        << error;
    for (std::size_t k = 0; k < document.nodes.size(); ++k) {
        if (document.nodes[k].extras_json_string.empty()) continue;
        document.nodes[k].extras = read.nodes.at(k).extras;
        document.nodes[k].extras_json_string.clear();
    }
    return document;
}

// tinygltf's writer on the same document: the .gltf text (buffer 0 as a data
// URI, as its stream writer always writes buffers) and the .glb bytes.
std::string tinygltf_text(const tinygltf::Model& document, bool binary) {
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(nullptr, nullptr);
    std::ostringstream stream;
    tinygltf::Model with_values = with_extras_values(document);
    with_values.buffers.at(0).uri.clear();  // a .gltf's .bin file name: gltf_text takes buffer 0's uri apart
    writer.WriteGltfSceneToStream(&with_values, stream, false, binary);
    return stream.str();
}

// A .glb's JSON chunk and the rest (its BIN chunk), from the header's lengths (glTF 2.0, 4.4).
std::pair<std::string, std::string> glb_chunks(const std::string& glb) {
    std::uint32_t json_length = 0;
    std::memcpy(&json_length, glb.data() + 12, 4);
    return {glb.substr(20, json_length), glb.substr(20 + json_length)};
}

// JSON text with each number outside strings as '#'.
std::string numbers_masked(const std::string& text) {
    std::string out;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            out += c;
            if (c == '\\') out += text[++i];
            in_string = c != '"';
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            while (i + 1 < text.size() && std::strchr("0123456789.eE+-", text[i + 1])) ++i;
            out += '#';
        } else {
            out += c;
            in_string = c == '"';
        }
    }
    return out;
}

// The same JSON (numbers as the same doubles: tinygltf's Grisu2 sometimes
// writes more digits than the shortest that read back, 0.21500001999999999
// for 0.21500002), the same layout around them, and the same binary chunk.
void expect_as_tinygltf_writes(const tinygltf::Model& document) {
    const std::vector<unsigned char>& bin = document.buffers.at(0).data;
    const std::string data_uri = "data:application/octet-stream;base64," + test::base64(bin);
    const std::string ours = gltf_text(document, data_uri), theirs = tinygltf_text(document, false);
    EXPECT_EQ(nlohmann::json::parse(ours), nlohmann::json::parse(theirs));
    EXPECT_TRUE(numbers_masked(ours) == numbers_masked(theirs));  // laid out alike
    auto [our_json, our_bin] = glb_chunks(glb_bytes(document));
    auto [their_json, their_bin] = glb_chunks(tinygltf_text(document, true));
    EXPECT_EQ(our_json.size() % 4, 0u);
    for (std::string* json : {&our_json, &their_json})
        json->erase(json->find_last_not_of(' ') + 1);  // the chunk's padding
    EXPECT_EQ(nlohmann::json::parse(our_json), nlohmann::json::parse(their_json));
    EXPECT_TRUE(numbers_masked(our_json) == numbers_masked(their_json));
    EXPECT_EQ(our_bin, their_bin);
}

}  // namespace

TEST(GltfJson, AFileNameBecomesAUriThatDecodesToIt) {
    EXPECT_EQ(file_uri("house_lod-2.bin"), "house_lod-2.bin");
    EXPECT_EQ(file_uri("my house%#?.png"), "my%20house%25%23%3F.png");
    EXPECT_EQ(file_name_of_uri("my%20house%25+1.png"), "my house% 1.png");
    EXPECT_EQ(file_uri("stra\xc3\x9f"
                       "e~.bin"),
              "stra%C3%9Fe~.bin");
}

// The FZK-Haus and a chain of its levels (MSFT_lod, pages, level buffers as
// data URIs): the same text and bytes as tinygltf writes, byte for byte.
TEST(GltfJson, WritesWhatTinygltfWritesForAModelAndAChain) {
    const Model house = read_model(test::fzk_haus_ifc);
    auto folder = test::scratch_folder("gltf_json");
    expect_as_tinygltf_writes(gltf_document({&house}, {}, folder / "house.glb", true, 2));
    std::vector<Level> chain;
    for (int c : {0, 3, 5}) chain.push_back(build_level(house, LodParameters{}, c, 2));
    std::vector<const Model*> levels;
    std::vector<LodSwitch> switches;
    for (const Level& level : chain) {
        levels.push_back(&level.model);
        if (levels.size() > 1) switches.push_back(LodSwitch{10.0 * level.level, 1.0 / level.level, 0, 0});
    }
    expect_as_tinygltf_writes(gltf_document(levels, switches, folder / "chain.glb", true, 2));
    expect_as_tinygltf_writes(gltf_document(levels, switches, folder / "chain.gltf", false, 2));
}

// What the models above do not hold: strings with every escape, numbers in
// each of nlohmann's layouts, tinygltf's quirks (an empty array is null, an
// empty extension {}), defaults left out and set.
TEST(GltfJson, WritesEscapesNumbersAndQuirksAsTinygltfDoes) {
    tinygltf::Model d;
    d.asset.version = "2.0";
    tinygltf::Node node;
    node.name = "quote \" backslash \\ tab \t newline \n bell \x07 delete \x7f umlaut \xc3\xa4";
    node.translation = {1e-5, 1.5e-4, 0.1, -0.0, 0.0, 123456789.0, 1e15, 1e16, -2.5e300, 5e-324};
    node.rotation = {0, 0, 0.70710678118654752, 0.70710678118654752};
    node.extras = tinygltf::Value(tinygltf::Value::Object{
        {"empty", tinygltf::Value(tinygltf::Value::Array{})},
        {"nulls", tinygltf::Value(tinygltf::Value::Array{tinygltf::Value()})},
        {"mixed", tinygltf::Value(
                      tinygltf::Value::Array{tinygltf::Value(3), tinygltf::Value(), tinygltf::Value(false)})},
        {"z", tinygltf::Value(0.3)}});
    node.extensions["EXT_empty"] = tinygltf::Value(tinygltf::Value::Object{});
    node.extensions["EXT_null"] = tinygltf::Value();
    node.children = {1};
    d.nodes = {node, tinygltf::Node()};
    d.nodes[1].name = "child";
    tinygltf::Material material;
    material.alphaMode = "MASK";
    material.alphaCutoff = 0.25;
    material.doubleSided = true;
    material.emissiveFactor = {0.5, 0, 0};
    material.normalTexture.index = 0;
    material.normalTexture.scale = 0.5;
    material.pbrMetallicRoughness.metallicFactor = 0;
    d.materials = {material, tinygltf::Material()};
    d.samplers.push_back(tinygltf::Sampler());
    d.scenes.push_back(tinygltf::Scene());
    d.scenes[0].nodes = {0};
    d.defaultScene = 0;
    d.buffers.resize(2);
    d.buffers[0].data = {1, 2, 3};
    d.buffers[1].data = {4, 5};
    expect_as_tinygltf_writes(d);
}

// Members it does not write are refused, not dropped.
TEST(GltfJson, RefusesWhatItDoesNotWrite) {
    tinygltf::Model d;
    d.animations.emplace_back();
    EXPECT_THROW(gltf_text(d, "x.bin"), std::logic_error);
    tinygltf::Model sparse;
    sparse.accessors.emplace_back().sparse.isSparse = true;
    EXPECT_THROW(glb_bytes(sparse), std::logic_error);
}
