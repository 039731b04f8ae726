#include "toolkit/formats/assimp_input_check.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

using namespace boxlod;

namespace {

std::string problem(const std::string& bytes, const std::string& extension) {
    return test::input_error_of([&] { check_assimp_input(bytes, extension, "m" + extension); });
}

}  // namespace

TEST(AssimpInputCheck, PlyCountsMustFitTheFile) {
    std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    EXPECT_EQ(problem(header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ".ply"), "");
    // assimp read on past an entry into the next ones (a face "200 0 1 2" became 199 triangles).
    EXPECT_EQ(problem(header + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n", ".ply"),
              "m.ply: line 13: element 'face' entry 0: 4 numbers where its properties take 201");
    EXPECT_EQ(problem(header + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", ".ply"),
              "m.ply: line 13: element 'face' entry 0: 3 numbers where its properties take 4");
    // An entry per line: a list shorter than its count, made up by the next line, is refused too.
    EXPECT_EQ(problem(header + "0 0 0\n1 0 0\n0 1\n0\n3 0 1 2\n", ".ply"),
              "m.ply: line 12: element 'vertex' entry 2: 2 numbers where its properties take 3");
    EXPECT_EQ(problem(header + "0 0 0\n1 0 0\n0 1 0\n\n\n", ".ply"),
              "m.ply: line 15: the file ends at element 'face' entry 0 of 1 (truncated file?)");
    std::string huge = "ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\nend_header\n0\n";
    EXPECT_EQ(
        problem(huge, ".ply"),
        "m.ply: line 3: element 'vertex': claims 1000000000 entries, more than the file's 2 bytes can hold");
    std::string binary =
        "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\nend_header\n" +
        std::string(15, '\0');
    EXPECT_NE(problem(binary, ".ply"), "");  // 2 doubles need 16 bytes
    std::string overflow =
        "ply\nformat ascii 1.0\nelement vertex 18446744073709551615\nproperty float x\nend_header\n";
    EXPECT_NE(problem(overflow, ".ply"), "");
    // assimp looped for ever on a header cut short, and took a minute over 400,000 empty elements.
    EXPECT_EQ(problem("ply\nformat ascii 1.0\ncomment x", ".ply"),
              "m.ply: the header has no 'end_header' line (truncated file?)");
    std::string many = "ply\nformat ascii 1.0\n";
    for (int i = 0; i < 1001; ++i) many += "element e 0\nproperty float a\n";
    EXPECT_EQ(problem(many + "end_header\n", ".ply"), "m.ply: line 2003: more than 1000 elements");
}

TEST(AssimpInputCheck, OffCountsMustFitTheFile) {
    EXPECT_EQ(problem("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ".off"), "");
    std::string huge = "OFF\n999999999 1 0\n0 0 0\n";
    EXPECT_EQ(problem(huge, ".off"),
              "m.off: line 2: vertex count: claims 999999999 entries, more than the file's " +
                  std::to_string(huge.size()) + " bytes can hold");
    // The counts may follow the keyword on its own line; comments are skipped.
    EXPECT_EQ(problem("# a triangle\nOFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ".off"), "");
    // assimp would clamp an index out of range to the last vertex.
    EXPECT_EQ(problem("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n", ".off"),
              "m.off: line 6: vertex index 9 is not one of the 3 vertices (0 to 3 - 1)");
    // A negative index is reported as written (it read as 18446744073709551615).
    EXPECT_EQ(problem("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", ".off"),
              "m.off: line 6: vertex index -1 is not one of the 3 vertices (0 to 3 - 1)");
    // assimp read "2.7" as 2, and a face cut short or a missing one as a face without indices.
    EXPECT_EQ(problem("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1.7\n", ".off"),
              "m.off: line 6: vertex index 1.7 is not one of the 3 vertices (0 to 3 - 1)");
    EXPECT_EQ(problem("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n", ".off"),
              "m.off: line 6: a face of 3 corners gives 2 vertex indices");
    EXPECT_EQ(problem("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ".off"),
              "m.off: line 2: the file ends at face 1 of 2 (truncated file?)");
}

// assimp opens an OBJ's material library itself: a FIFO blocked it for ever, a folder read as "File read
// error" naming neither; one that is missing is a warning, as assimp draws its materials grey.
TEST(AssimpInputCheck, AnObjsMaterialLibraryIsARegularFileOrMissing) {
    const std::filesystem::path folder = test::scratch_folder("obj_mtllib");
    std::filesystem::create_directory(folder / "folder.mtl");
    ASSERT_EQ(::mkfifo((folder / "fifo.mtl").c_str(), 0600), 0);
    test::write_text(folder / "real.mtl", "newmtl m\nKd 1 0 0\n");
    const std::string file = (folder / "m.obj").string();
    auto problem_with = [&](const std::string& library) {
        return test::input_error_of(
            [&] { check_assimp_input("v 0 0 0\n  mtllib " + library + " \r\nf 1 1 1\n", ".obj", file); });
    };
    EXPECT_EQ(problem_with("fifo.mtl"),
              file + ": line 2: mtllib 'fifo.mtl' is not a regular file (a folder, FIFO or device)");
    EXPECT_EQ(problem_with("folder.mtl"),
              file + ": line 2: mtllib 'folder.mtl' is not a regular file (a folder, FIFO or device)");
    EXPECT_EQ(problem_with("real.mtl"), "");
    EXPECT_EQ(problem_with("missing.mtl"), "");
    // Where the library named is missing, assimp reads the OBJ's own name with .mtl.
    ASSERT_EQ(::mkfifo((folder / "m.mtl").c_str(), 0600), 0);
    EXPECT_EQ(problem_with("missing.mtl"),
              file + ": line 2: mtllib 'm.mtl' is not a regular file (a folder, FIFO or device)");
}

// assimp read these as 0, or dropped the index and with it the material's texture, without a word.
TEST(AssimpInputCheck, ObjNumbersAreFiniteAndItsIndicesNameWhatTheFileHas) {
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
    EXPECT_EQ(problem(triangle + "f 1/1/1 2/1/1 -1/-1/-1 # a comment\nf 1//1 2//1 \\\n 3//1\n", ".obj"), "");
    EXPECT_EQ(problem("v 0x10 0 0\n", ".obj"), "m.obj: line 1: '0x10' is not a finite number");
    EXPECT_EQ(problem("v +1 -2. +3.1e2\n", ".obj"), "");  // as assimp's number_formats.obj
    EXPECT_EQ(problem("v 1 2 3.1+e2\n", ".obj"), "m.obj: line 1: '3.1+e2' is not a finite number");
    EXPECT_EQ(problem(triangle + "vt nan 0.25\n", ".obj"), "m.obj: line 6: 'nan' is not a finite number");
    EXPECT_EQ(problem(triangle + "vt 1e39 0.25\n", ".obj"), "m.obj: line 6: '1e39' is not a finite number");
    EXPECT_EQ(problem(triangle + "f 1/9 2/1 3/1\n", ".obj"),
              "m.obj: line 6: corner '1/9': texture coordinate index '9' is not one of the 1 texture "
              "coordinates in the file");
    EXPECT_EQ(problem(triangle + "f 1//7 2//1 3//1\n", ".obj"),
              "m.obj: line 6: corner '1//7': normal index '7' is not one of the 1 normals in the file");
    EXPECT_EQ(problem("v 0 0 0\nf -2 1 1\nv 1 0 0\n", ".obj"),
              "m.obj: line 2: corner '-2': vertex index '-2' is not one of the 1 vertices before it");
    EXPECT_EQ(problem(triangle + "f 1 2\n", ".obj"), "m.obj: line 6: a face of fewer than 3 corners");
    // Lines may end in a lone CR; a NaN normal reads as 0, and boxlod makes the part's normals anew.
    EXPECT_EQ(problem("v 0 0 0\rv 1 0 0\rv 0 1 0\rvn nan 0 1\rf 1//1 2//1 3//1\r", ".obj"), "");
    EXPECT_EQ(problem("v 0 0 0\r\nf 1 1 x\r\n", ".obj"),
              "m.obj: line 2: corner 'x': vertex index 'x' is not one of the 1 vertices in the file");
    EXPECT_EQ(problem(triangle + "f 1/1/1/1 2 3\n", ".obj"),
              "m.obj: line 6: corner '1/1/1/1' has more than 3 indices");
}

// assimp drew a facet of four vertices as one triangle without a word.
TEST(AssimpInputCheck, AnAsciiStlFacetHoldsThreeVertices) {
    const std::string facet =
        "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n";
    EXPECT_EQ(problem("solid a\n" + facet + " endloop\nendfacet\nendsolid a\n", ".stl"), "");
    EXPECT_EQ(problem("solid a\n" + facet + "  vertex 1 1 0\n endloop\nendfacet\nendsolid a\n", ".stl"),
              "m.stl: line 3: a facet's loop of 4 vertices (STL's hold 3)");
    // A binary STL whose header starts with "solid" is told by its size.
    std::string binary =
        "solid but binary" + std::string(64, ' ') + std::string("\1\0\0\0", 4) + std::string(50, '\0');
    EXPECT_EQ(problem(binary, ".stl"), "");
}

namespace {

// A binary FBX 7400 of `depth` records "A" nested in one another, each list closed by a null record.
std::string nested_binary_fbx(int depth) {
    std::string out("Kaydara FBX Binary  \0\x1a\0", 23);
    const auto append = [&](std::uint32_t value) { out.append(reinterpret_cast<const char*>(&value), 4); };
    append(7400);
    std::vector<std::uint32_t> ends(std::size_t(depth), 27 + 14 * std::uint32_t(depth));  // 14: header + "A"
    for (int i = depth - 2; i >= 0; --i) ends[std::size_t(i)] = ends[std::size_t(i) + 1] + 13;
    for (std::uint32_t end : ends) {
        append(end);
        append(0);
        append(0);
        out +=
            "\x01"
            "A";
    }
    return out + std::string(13 * std::size_t(depth), '\0');  // depth - 1 nested lists' and the top's
}

}  // namespace

// assimp's FBX parsers recurse per scope: 200,000 nested scopes crashed them.
TEST(AssimpInputCheck, FbxScopesNestAtMostTheLimit) {
    std::string deep = "; FBX 7.4.0 project file\n; {{{ in a comment\nObjects: {\n  Name: \"{{{\"\n";
    for (int i = 0; i < 199; ++i) deep += "A: {";
    EXPECT_EQ(problem(deep, ".fbx"), "");
    EXPECT_EQ(problem(deep + "A: {", ".fbx").rfind("m.fbx: byte ", 0), 0u);
    EXPECT_NE(problem(deep + "A: {", ".fbx").find("FBX scopes nested more than 200 levels deep"),
              std::string::npos);
    EXPECT_EQ(problem(nested_binary_fbx(5), ".fbx"), "");
    EXPECT_NE(problem(nested_binary_fbx(300), ".fbx").find("FBX scopes nested more than 200 levels deep"),
              std::string::npos);
    // Cut short or with offsets that make no sense, it is left to assimp, which refuses it.
    EXPECT_EQ(problem(nested_binary_fbx(300).substr(0, 40), ".fbx"), "");
    // Read as assimp reads them (a review of the check): binary by the first 18 bytes, a comment ended by
    // '\r' too.
    std::string renamed = nested_binary_fbx(300);
    renamed.replace(18, 3, "XYZ");
    EXPECT_NE(problem(renamed, ".fbx").find("FBX scopes nested"), std::string::npos);
    std::string returns = "; a comment to a carriage return\r";
    for (int i = 0; i < 201; ++i) returns += "A: {";
    EXPECT_NE(problem(returns, ".fbx").find("FBX scopes nested"), std::string::npos);
}
