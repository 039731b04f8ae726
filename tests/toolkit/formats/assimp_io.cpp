#include "toolkit/formats/assimp_io.h"

#include "base/input_error.h"
#include "base/memory_budget.h"
#include "test_support.h"
#include "toolkit/formats/model_bytes.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/model/statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

using namespace boxlod;
namespace fs = std::filesystem;

namespace {
std::string statistic(const Model& model, const std::string& key) {
    return value_of(model_statistics(model), key);
}
}  // namespace

TEST(AssimpIo, ObjQuadsCountAsOneFaceEach) {
    auto folder = test::scratch_folder("assimp_obj");
    test::write_text(folder / "box.obj", R"(o wall
v 0 0 0
v 2 0 0
v 2 3 0
v 0 3 0
v 0 0 1
f 1 2 3 4
f 1 2 5
)");
    Model model = load_model((folder / "box.obj").string());
    MeshCounts counts = mesh_counts(model);
    EXPECT_EQ(counts.faces, 2u);      // one quad, one triangle
    EXPECT_EQ(counts.triangles, 3u);  // the quad fans into two
    EXPECT_EQ(model_bounds(model).size(), Eigen::Vector3f(2, 3, 1));
}

// Names in a legacy encoding (assimp's regr01.obj: "usemtl Terraind\xe6k",
// Latin-1) come in as UTF-8, which glTF's JSON must hold: writing the raw
// bytes failed inside the JSON writer (exit 1).
TEST(AssimpIo, Latin1NamesBecomeUtf8) {
    auto folder = test::scratch_folder("assimp_latin1");
    test::write_text(folder / "m.mtl", "newmtl Terraind\xe6k\nKd 0.5 0.5 0.5\n");
    test::write_text(
        folder / "m.obj",
        "mtllib m.mtl\ng Gel\xe4nde\nusemtl Terraind\xe6k\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Model model = load_model((folder / "m.obj").string());
    const auto material = std::find_if(model.materials.begin(), model.materials.end(),
                                       [](const Material& m) { return m.name.starts_with("Terrain"); });
    ASSERT_NE(material, model.materials.end());
    EXPECT_EQ(material->name, "Terraind\xc3\xa6k");
    EXPECT_TRUE(std::any_of(model.nodes.begin(), model.nodes.end(),
                            [](const Node& n) { return n.name == "Gel\xc3\xa4nde"; }));
    save_model(model, (folder / "m.gltf").string());
    const Model read_back = load_model((folder / "m.gltf").string());
    EXPECT_TRUE(std::any_of(read_back.materials.begin(), read_back.materials.end(),
                            [](const Material& m) { return m.name == "Terraind\xc3\xa6k"; }));
}

// MTL's colours may lie beyond [0, 1] ("increase the reflectivity"); glTF's factors may not: clamped.
TEST(AssimpIo, ColoursBeyondOneAreClamped) {
    auto folder = test::scratch_folder("assimp_bright");
    test::write_text(folder / "m.mtl", "newmtl lamp\nKd 1.5 0.5 -0.25\nKs 2 2 2\n");
    test::write_text(folder / "m.obj", "mtllib m.mtl\nusemtl lamp\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Model model = load_model((folder / "m.obj").string());
    const auto lamp = std::find_if(model.materials.begin(), model.materials.end(),
                                   [](const Material& m) { return m.name == "lamp"; });
    ASSERT_NE(lamp, model.materials.end());
    EXPECT_EQ(lamp->base_color, Eigen::Vector4f(1, 0.5f, 0, 1));
    EXPECT_EQ(lamp->specular_color, Eigen::Vector3f(1, 1, 1));
}

TEST(AssimpIo, MalformedFilesAreInputErrors) {
    auto folder = test::scratch_folder("assimp_bad");
    test::write_text(folder / "bad.ply",
                     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n");
    EXPECT_THROW(load_model((folder / "bad.ply").string()), InputError);
    test::write_text(folder / "bad.obj", "f 1 2 3\n");
    EXPECT_THROW(load_model((folder / "bad.obj").string()), InputError);
    test::write_text(folder / "empty.off", "");
    EXPECT_THROW(load_model((folder / "empty.off").string()), InputError);
}

// AC3D objects nested 100,000 deep crash assimp (its reader recurses per
// object's kids): its isolated read (docs/design.md: Errors) makes that one
// InputError naming the file and the reader.
TEST(AssimpIo, ACrashInsideAssimpIsAnInputError) {
    const auto file = test::scratch_folder("assimp_crash") / "deep.ac";
    std::string text =
        "AC3Db\nMATERIAL \"m\" rgb 1 1 1  amb 0.2 0.2 0.2  emis 0 0 0  spec 0 0 0  shi 10  trans 0\n"
        "OBJECT world\nkids 1\n";
    for (int i = 0; i < 100000; ++i) text += "OBJECT group\nkids 1\n";
    text +=
        "OBJECT poly\nnumvert 3\n0 0 0\n1 0 0\n0 1 0\nnumsurf 1\nSURF 0x20\nmat 0\nrefs 3\n0 0 0\n1 0 0\n2 0 "
        "0\nkids 0\n";
    test::write_text(file, text);
    const std::string error = test::input_error_of([&] { import_with_assimp(file.string()); });
    EXPECT_EQ(error.find(file.string() + ": assimp's importer crashed on this file"), 0u) << error;
}

// One file of each format the original program's users have, from Debian's assimp-testmodels.
TEST(AssimpIo, EveryFormatReadsWithItsHierarchy) {
    struct Case {
        const char* file;
        const char* nodes;
        const char* depth;
        const char* faces;
    };
    const Case cases[] = {
        {"FBX/cubes_with_names.fbx", "5", "2", "210"},
        {"Collada/duck.dae", "4", "1", "2144"},
        {"PLY/cube.ply", "1", "0", "6"},
        {"OFF/Cube.off", "1", "0", "6"},
        {"3DS/fels.3ds", "2", "1", "768"},
        {"OBJ/box.obj", "2", "1", "6"},
    };
    for (const Case& c : cases) {
        Model model = load_model(std::string("/usr/share/assimp/models/") + c.file);
        EXPECT_EQ(statistic(model, "nodes"), c.nodes) << c.file;
        EXPECT_EQ(statistic(model, "depth"), c.depth) << c.file;
        EXPECT_EQ(statistic(model, "faces_original"), c.faces) << c.file;
    }
    // The file names TEST.PNG, the folder holds test.png: texture names that
    // differ in letter case from the files still load.
    Model textured = load_model("/usr/share/assimp/models/3DS/cube_with_diffuse_texture.3DS");
    ASSERT_EQ(textured.textures.size(), 1u);
    EXPECT_GT(textured.textures[0].image.width, 0);
}

// Files written on Windows name their textures with backslashes (spider.obj:
// ".\wal67ar_small.jpg"; test.x: ".\test.png") or by the author's absolute
// path: read from the folder or beside the model, they load.
TEST(AssimpIo, TexturesNamedAsOnWindowsLoad) {
    for (const char* file : {"OBJ/spider.obj", "X/test.x"}) {
        Model model = load_model(std::string("/usr/share/assimp/models/") + file);
        ASSERT_FALSE(model.textures.empty()) << file;
        EXPECT_GT(model.textures[0].image.width, 0) << file;
    }
    auto folder = test::scratch_folder("assimp_windows_path");
    fs::copy_file("/usr/share/assimp/models/X/test.png", folder / "Wall.png",
                  fs::copy_options::overwrite_existing);
    test::write_text(folder / "m.mtl",
                     "newmtl wall\nKd 1 1 1\nmap_Kd C:\\Users\\author\\textures\\wall.png\n");
    test::write_text(
        folder / "m.obj",
        "mtllib m.mtl\nusemtl wall\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
    Model model = load_model((folder / "m.obj").string());
    ASSERT_EQ(model.textures.size(), 1u);
    EXPECT_GT(model.textures[0].image.width, 0);
    EXPECT_EQ(model.read_files, std::vector<std::string>{(folder / "Wall.png").string()});  // as found
    fs::create_directories(folder / "maps");
    fs::copy_file("/usr/share/assimp/models/X/test.png", folder / "maps" / "stone.png",
                  fs::copy_options::overwrite_existing);
    test::write_text(
        folder / "m.mtl",
        "newmtl wall\nKd 1 1 1\nmap_Kd //maps/stone.png\n");  // Blender's "from the .blend's folder"
    EXPECT_EQ(load_model((folder / "m.obj").string()).textures.size(), 1u);
    test::write_text(folder / "m.mtl", "newmtl wall\nKd 1 1 1\nmap_Kd C:\\Users\\author\\missing.png\n");
    EXPECT_NE(test::input_error_of([&] {
                  load_model((folder / "m.obj").string());
              }).find("missing.png: no such file"),
              std::string::npos);
}

// An image several materials name is decoded once, and each decoded image
// counts against the memory budget while the next is decoded (three materials
// on one 8192 x 8192 PNG were refused as one image needing three times its
// memory; seven large PNGs ran out of memory blaming a valid file).
TEST(AssimpIo, AnImageManyMaterialsNameIsDecodedOnce) {
    auto folder = test::scratch_folder("assimp_shared_image");
    fs::copy_file("/usr/share/assimp/models/X/test.png", folder / "wall.png",
                  fs::copy_options::overwrite_existing);
    std::string materials, faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";
    for (const char* name : {"a", "b", "c"}) {
        materials += std::string("newmtl ") + name + "\nKd 1 1 1\nmap_Kd wall.png\n";
        faces += std::string("usemtl ") + name + "\nf 1/1 2/2 3/3\n";
    }
    test::write_text(folder / "m.mtl", materials);
    test::write_text(folder / "m.obj", "mtllib m.mtl\n" + faces);
    // In this process (load_model reads in a child) with a budget for one 512 x 512 image's decoding
    // (8 bytes a pixel) and a little more, not for its decoded pixels (4 bytes a pixel) besides.
    test::MemoryBudgetScope scope;
    set_memory_budget(10.0 * 512 * 512);
    const Model model = import_with_assimp_in_process((folder / "m.obj").string());
    ASSERT_EQ(model.textures.size(), 1u);
    int named = 0;
    for (const Material& material : model.materials) named += material.base_color_texture == 0;
    EXPECT_EQ(named, 3);
    EXPECT_EQ(held_memory(), 0);  // nothing held once the model is read
    fs::copy_file(folder / "wall.png", folder / "roof.png", fs::copy_options::overwrite_existing);
    test::write_text(folder / "m.mtl", materials + "newmtl d\nKd 1 1 1\nmap_Kd roof.png\n");
    test::write_text(folder / "m.obj", "mtllib m.mtl\n" + faces + "usemtl d\nf 1/1 2/2 3/3\n");
    EXPECT_NE(test::input_error_of([&] {
                  import_with_assimp_in_process((folder / "m.obj").string());
              }).find("roof.png: decoding its 512x512 pixels would need 2.1 MB beside the 1.05 MB held"),
              std::string::npos);
}

// LightWave maps textures by projection (planar, cylindrical, spherical):
// assimp's GenUVCoords turns each into the texture coordinates glTF needs.
TEST(AssimpIo, ProjectionMappedTexturesGetTextureCoordinates) {
    for (const char* file : {"earth_planar_z.lwo", "earth_cylindrical_y.lwo", "earth_spherical_x.lwo"}) {
        const Model model = load_model(std::string("/usr/share/assimp/models/LWO/LWO2/MappingModes/") + file);
        int textured = 0;
        for (const Node& node : model.nodes)
            for (const Primitive& primitive : node.primitives)
                if (primitive.material >= 0 &&
                    samples_textures(model.materials[std::size_t(primitive.material)])) {
                    EXPECT_EQ(primitive.uvs.size(), primitive.positions.size()) << file;
                    ++textured;
                }
        EXPECT_GT(textured, 0) << file;
    }
}

// Every command reads through the isolated reader (a child process, the scene
// handed back field for field); it gives the model the reader gives in this
// process, textures and all.
TEST(AssimpIo, TheIsolatedReadIsTheInProcessRead) {
    for (const char* file :
         {"FBX/cubes_with_names.fbx", "Collada/duck.dae", "PLY/cube.ply", "OFF/Cube.off", "3DS/fels.3ds",
          "OBJ/box.obj", "3DS/cube_with_diffuse_texture.3DS", "IFC/AC14-FZK-Haus.ifc"}) {
        const std::string path = std::string("/usr/share/assimp/models/") + file;
        const Model isolated = import_with_assimp(path), in_process = import_with_assimp_in_process(path);
        EXPECT_EQ(isolated.source, in_process.source) << file;
        EXPECT_EQ(isolated.nodes.size(), in_process.nodes.size()) << file;
        EXPECT_EQ(isolated.materials, in_process.materials) << file;
        EXPECT_TRUE(model_bytes(isolated) == model_bytes(in_process)) << file;  // every field
    }
}

// Real data made by others: the KIT FZK-Haus, read from IFC directly by
// assimp (boxlod reads IFC by web-ifc; assimp's reading is the peer of its
// benchmark and tests) and from the glTF that assimp's own exporter makes of it.
TEST(AssimpIo, FzkHausIfcKeepsItsHierarchy) {
    Model model = import_with_assimp(test::fzk_haus_ifc);
    EXPECT_EQ(statistic(model, "nodes"), "216");
    EXPECT_EQ(statistic(model, "depth"), "7");
    EXPECT_EQ(statistic(model, "triangles_original"), "35906");
}

// Its glass (IfcSurfaceStyleRendering transparency 0.88) reads as BLEND with
// alpha 0.12, and a glTF written from it keeps both.
TEST(AssimpIo, FzkHausGlassIsBlendedAndKeptByConvert) {
    Model model = import_with_assimp(test::fzk_haus_ifc);
    auto is_glass = [](const Material& m) { return m.alpha_mode == AlphaMode::blend; };
    auto glass = std::find_if(model.materials.begin(), model.materials.end(), is_glass);
    ASSERT_NE(glass, model.materials.end());
    EXPECT_NEAR(glass->base_color.w(), 0.12f, 1e-6);
    for (const Material& m : model.materials)
        if (!is_glass(m)) {
            EXPECT_EQ(m.base_color.w(), 1) << m.name;
        }
    auto folder = test::scratch_folder("assimp_fzk_glass");
    save_model(model, (folder / "fzk.glb").string());
    Model again = load_model((folder / "fzk.glb").string());
    auto kept = std::find_if(again.materials.begin(), again.materials.end(), is_glass);
    ASSERT_NE(kept, again.materials.end());
    EXPECT_EQ(kept->name, glass->name);
    EXPECT_NEAR(kept->base_color.w(), 0.12f, 1e-6);
}

TEST(AssimpIo, FzkHausGlbFromAssimpExportKeepsItsHierarchy) {
    auto folder = test::scratch_folder("assimp_fzk");
    std::string glb = (folder / "fzk.glb").string();
    std::string command =
        std::string("assimp export ") + test::fzk_haus_ifc + " " + glb + " -fglb2 >/dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    Model model = load_model(glb);
    EXPECT_EQ(statistic(model, "nodes"), "216");
    EXPECT_EQ(statistic(model, "depth"), "7");
    EXPECT_EQ(statistic(model, "triangles_original"), "35906");
}
