#include "toolkit/formats/gltf_structure.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

using namespace boxlod;

namespace {

std::string problem(const std::string& bytes, bool binary = false) {
    return test::input_error_of([&] { check_gltf_structure(bytes, binary, "m.gltf"); });
}

std::string u32(std::uint32_t v) { return {char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; }

// A glb of one JSON chunk and one BIN chunk of `bin` bytes; `declared` overrides the total length.
std::string glb(const std::string& json, std::size_t bin, std::uint32_t declared = 0) {
    std::string body = u32(std::uint32_t(json.size())) + "JSON" + json + u32(std::uint32_t(bin)) + "BIN" +
                       '\0' + std::string(bin, '\0');
    return "glTF" + u32(2) + u32(declared ? declared : std::uint32_t(12 + body.size())) + body;
}

const std::string buffer_and_view =
    R"({"buffers":[{"byteLength":16}],"bufferViews":[{"buffer":0,"byteOffset":)";

}  // namespace

TEST(GltfStructure, AcceptsAWellFormedFile) {
    EXPECT_EQ(problem(buffer_and_view + R"(8,"byteLength":8}]})"), "");
    EXPECT_EQ(problem(glb(buffer_and_view + R"(0,"byteLength":16}]})", 16), true), "");
}

TEST(GltfStructure, RefusesNestingDeeperThanTheLimit) {
    std::string deep = R"({"asset":{"extras":)" + std::string(20000, '[') + std::string(20000, ']') + "}}";
    EXPECT_NE(problem(deep).find("JSON nested more than 200 levels deep"), std::string::npos);
    // Brackets inside strings do not count.
    EXPECT_EQ(problem(R"({"asset":{"name":")" + std::string(1000, '[') + R"("}})"), "");
}

TEST(GltfStructure, RefusesBufferViewsOutsideTheirBufferWithoutOverflow) {
    EXPECT_EQ(problem(buffer_and_view + R"(18446744073709551608,"byteLength":16}]})"),
              "m.gltf: bufferView 0: byteOffset 18446744073709551608 + byteLength 16 runs past buffer 0's 16 "
              "bytes");
    EXPECT_EQ(problem(buffer_and_view + R"(8,"byteLength":9}]})"),
              "m.gltf: bufferView 0: byteOffset 8 + byteLength 9 runs past buffer 0's 16 bytes");
    EXPECT_EQ(problem(buffer_and_view + R"(-1,"byteLength":9}]})"),
              "m.gltf: bufferView 0: byteOffset must be a non-negative integer");
    EXPECT_EQ(problem(R"({"bufferViews":[{"buffer":3,"byteLength":1}]})"),
              "m.gltf: bufferView 0: buffer index out of range");
    EXPECT_EQ(problem(R"({"images":[{"bufferView":0}]})"), "m.gltf: image 0: bufferView index out of range");
}

TEST(GltfStructure, RefusesGlbHeadersAndChunksThatDoNotFitTheFile) {
    std::string json = buffer_and_view + R"(0,"byteLength":16}]})";
    EXPECT_EQ(problem(glb(json, 16, 1000), true), "m.gltf: header: declares 1000 bytes, the file has " +
                                                      std::to_string(glb(json, 16).size()) +
                                                      " (truncated file?)");
    std::string truncated = glb(json, 16);
    truncated.resize(truncated.size() - 8);
    truncated.replace(8, 4, u32(std::uint32_t(truncated.size())));
    EXPECT_EQ(problem(truncated, true), "m.gltf: chunk 1: runs past the end of the file (truncated file?)");
    EXPECT_EQ(problem(glb(json, 8), true),
              "m.gltf: buffer 0: byteLength 16 exceeds the 8-byte BIN chunk (truncated file?)");
    EXPECT_EQ(problem("glTF" + u32(1) + u32(20) + u32(0) + "JSON", true),
              "m.gltf: header: glb version is not 2");
    EXPECT_EQ(problem("not a glb at all, really", true), "m.gltf: not a glb file (no 'glTF' header)");
}

TEST(GltfStructure, NamesMalformedJson) {
    EXPECT_EQ(problem(R"({"buffers":[)").rfind("m.gltf: malformed JSON: ", 0), 0u);
    EXPECT_EQ(problem("[1, 2]"), "m.gltf: the JSON is not an object");
}

TEST(GltfStructure, MembersBoxlodReadsHaveTheirSchemasKind) {
    // tinygltf skipped each of these without a word, as if the member were absent.
    EXPECT_EQ(problem(R"({"materials":[{"alphaCutoff":"x"}]})"),
              "m.gltf: materials[0].alphaCutoff: must be a number");
    EXPECT_EQ(problem(R"({"materials":[{},{"doubleSided":"yes"}]})"),
              "m.gltf: materials[1].doubleSided: must be true or false");
    EXPECT_EQ(
        problem(R"({"materials":[{"pbrMetallicRoughness":{"baseColorFactor":[1,1,1]}}]})"),
        "m.gltf: materials[0].pbrMetallicRoughness.baseColorFactor: must be an array of numbers of length 4");
    EXPECT_EQ(problem(R"({"meshes":[{"primitives":[{"attributes":{},"material":-1}]}]})"),
              "m.gltf: meshes[0].primitives[0].material: must be a non-negative integer below 2^31");
    // tinygltf keeps an index, and any integer in what boxlod reads of extras and extensions, in an int:
    // 2^32 would read as index 0, 2^32 + 1 as a colour of 1.
    EXPECT_EQ(
        problem(R"({"meshes":[{"primitives":[{"attributes":{"POSITION":4294967296}}]}]})"),
        "m.gltf: meshes[0].primitives[0].attributes: must be an object of non-negative integers below 2^31");
    EXPECT_EQ(problem(R"({"materials":[{"extensions":{"KHR_materials_pbrSpecularGlossiness":)"
                      R"({"diffuseFactor":[4294967297,0,0,1]}}}]})"),
              "m.gltf: materials[0].extensions.KHR_materials_pbrSpecularGlossiness: must be free of integers "
              "beyond 32 bits");
    EXPECT_EQ(problem(R"({"nodes":[{"extras":{"boxlod":{"scope":{"center":[-4294967296,0,0]}}}}]})"),
              "m.gltf: nodes[0].extras.boxlod: must be free of integers beyond 32 bits");
    EXPECT_EQ(problem(R"({"nodes":[{"extras":{"other_tool":{"id":18446744073709551615}}}]})"), "");
    EXPECT_EQ(problem(R"({"nodes":[{"mesh":4294967296}]})"),
              "m.gltf: nodes[0].mesh: must be a non-negative integer below 2^31");
    EXPECT_EQ(problem(R"({"nodes":[{"children":[1,"2"]}]})"),
              "m.gltf: nodes[0].children: must be an array of non-negative integers below 2^31");
    EXPECT_EQ(problem(R"({"extensionsUsed":"KHR_materials_specular"})"),
              "m.gltf: extensionsUsed: must be an array of strings");
    EXPECT_EQ(problem(R"({"meshes":{}})"), "m.gltf: meshes: must be an array");
    // Extensions are objects wherever they are; extras may hold anything.
    EXPECT_EQ(problem(R"({"nodes":[{"extensions":null}]})"),
              "m.gltf: nodes[0].extensions: must be an object");
    EXPECT_EQ(problem(R"({"materials":[{"normalTexture":{"index":0,"extensions":[]}}]})"),
              "m.gltf: materials[0].normalTexture.extensions: must be an object");
    EXPECT_EQ(
        problem(
            R"({"asset":{"version":"2.0","extras":{"extensions":[1]}},"materials":[{"alphaCutoff":0.5,"doubleSided":true}]})"),
        "");
}

// glTF 1.0 and Draco files are refused by what they are, before tinygltf reads
// them: it would fail on a member that 1.0 spells otherwise ("scene" a string)
// or on the compressed accessors, with a message that names neither.
TEST(GltfStructure, RefusesOtherVersionsAndRequiredExtensionsByName) {
    EXPECT_NE(problem(R"({"asset":{"version":"1.0"},"scene":"defaultScene"})")
                  .find("asset.version: '1.0' is not glTF 2"),
              std::string::npos);
    EXPECT_NE(
        problem(R"({"asset":{"version":1},"scene":"defaultScene"})").find("asset.version: 1 is not glTF 2"),
        std::string::npos);
    EXPECT_NE(
        problem(
            R"({"asset":{"version":"2.0"},"extensionsRequired":["KHR_draco_mesh_compression"],"accessors":[{"count":3}]})")
            .find(
                "extensionsRequired: 'KHR_draco_mesh_compression' is required, and boxlod does not read it"),
        std::string::npos);
    EXPECT_EQ(
        problem(R"({"asset":{"version":"2.0"},"extensionsRequired":["MSFT_lod","KHR_materials_specular"]})"),
        "");
}

TEST(GltfStructure, AUriNamesARelativeFileWithoutANul) {
    EXPECT_EQ(problem(R"({"images":[{"uri":"textures/a%20b.png"}]})"), "");
    EXPECT_NE(problem(R"({"images":[{"uri":"/etc/a.png"}]})").find("image 0: uri '/etc/a.png' is absolute"),
              std::string::npos);
    // "t.png%00zz" would read t.png: the file system takes a name up to its NUL.
    EXPECT_EQ(problem(R"({"buffers":[{"byteLength":1,"uri":"t.bin%00zz"}]})"),
              "m.gltf: buffer 0: uri 't.bin%00zz' names a file with a NUL character");
}
