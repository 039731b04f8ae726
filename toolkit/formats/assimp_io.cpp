#include "toolkit/formats/assimp_io.h"

#include "base/child_process.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/memory_budget.h"
#include "base/utf8.h"
#include "toolkit/formats/assimp_input_check.h"
#include "toolkit/formats/model_bytes.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <Eigen/LU>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>

namespace boxlod {
namespace {

namespace fs = std::filesystem;

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
    Eigen::Matrix4d out;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out(r, c) = m[r][c];
    return out;
}

// Polygons are kept as the file stores them for counting, and fanned into
// triangles (assimp's own triangulation would hide the polygon count).
Primitive convert_mesh(const aiMesh& mesh, const Eigen::Matrix4d& world) {
    Primitive out;
    Eigen::Matrix3d linear = world.topLeftCorner<3, 3>();
    Eigen::Matrix3d normal_matrix = linear.inverse().transpose();
    bool mirrored = linear.determinant() < 0;
    for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
        const aiVector3D& p = mesh.mVertices[i];
        out.positions.push_back(
            (linear * Eigen::Vector3d(p.x, p.y, p.z) + world.topRightCorner<3, 1>()).cast<float>());
        if (mesh.mNormals) {
            const aiVector3D& n = mesh.mNormals[i];
            Eigen::Vector3d normal = normal_matrix * Eigen::Vector3d(n.x, n.y, n.z);
            // Some exporters leave zero normals; keep them valid rather than NaN.
            out.normals.push_back(normal.norm() > 0 ? normal.normalized().cast<float>()
                                                    : Eigen::Vector3f(0, 0, 1));
        }
        if (mesh.mTextureCoords[0])
            out.uvs.emplace_back(mesh.mTextureCoords[0][i].x, mesh.mTextureCoords[0][i].y);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices < 3) continue;  // points and lines
        ++out.polygon_count;
        for (unsigned k = 2; k < face.mNumIndices; ++k) {
            std::uint32_t a = face.mIndices[0], b = face.mIndices[k - 1], c = face.mIndices[k];
            if (mirrored) std::swap(b, c);
            out.indices.insert(out.indices.end(), {a, b, c});
        }
    }
    out.material = int(mesh.mMaterialIndex);
    return out;
}

// A texture as files written on Windows name it: the exact path, else with
// backslashes as folder separators (".\wall.jpg"; Blender's "//wall.jpg" is
// in the model's folder), else its bare name beside the model (an absolute
// "C:\...\wall.jpg" of the author's machine), as Blender's "Find Missing
// Files" looks; each also in another letter case, as FBX and 3DS names often differ.
fs::path find_file(const fs::path& directory, const std::string& name) {
    auto lower = [](std::string s) {
        for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    auto found = [&](const fs::path& path) -> std::optional<fs::path> {
        std::error_code error;
        if (fs::exists(path, error)) return path;
        const std::string wanted = lower(path.filename().string());
        for (const auto& entry : fs::directory_iterator(path.parent_path(), error))
            if (lower(entry.path().filename().string()) == wanted) return entry.path();
        return std::nullopt;
    };
    std::string slashes = name;
    std::replace(slashes.begin(), slashes.end(), '\\', '/');
    if (slashes.starts_with("//")) slashes.erase(0, 2);  // Blender's "relative to the .blend file"
    const std::string bare = fs::path(slashes).filename().string();
    for (const fs::path& candidate : {directory / name, directory / slashes, directory / bare})
        if (auto path = found(candidate); path && !fs::is_directory(*path)) return *path;
    return directory / name;  // reading it gives the error that names the missing file
}

// The scene's textures as they are decoded: each image once however many
// materials name it, and each counted against the memory budget beside the
// ones decoded before (seven large PNGs ran out of memory one by one, and the
// message blamed a valid file).
struct TextureReading {
    const aiScene& scene;
    fs::path directory;
    std::map<std::string, int> decoded;  // by file, or "*" and an embedded texture's name
    double bytes = 0;
    MemoryHold held;
};

int load_texture(Model& model, TextureReading& reading, const aiMaterial& material, aiTextureType type) {
    aiString name;
    if (material.GetTexture(type, 0, &name) != AI_SUCCESS) return -1;
    std::string file = name.C_Str();
    const aiTexture* embedded = reading.scene.GetEmbeddedTexture(name.C_Str());
    const std::string key = embedded ? "*" + file : find_file(reading.directory, file).string();
    if (auto known = reading.decoded.find(key); known != reading.decoded.end()) return known->second;
    Texture texture;
    texture.name =
        utf8_or_latin1(fs::path(file).filename().string());  // the name; the file is read by its bytes
    if (embedded) {
        if (embedded->mHeight == 0) {
            texture.image = decode_image(
                {reinterpret_cast<const std::uint8_t*>(embedded->pcData), embedded->mWidth}, file);
        } else {
            texture.image = Image8(int(embedded->mWidth), int(embedded->mHeight), 4);
            for (std::size_t i = 0; i < std::size_t(embedded->mWidth) * embedded->mHeight; ++i) {
                const aiTexel& t = embedded->pcData[i];
                std::uint8_t* p = &texture.image.pixels[i * 4];
                p[0] = t.r;
                p[1] = t.g;
                p[2] = t.b;
                p[3] = t.a;
            }
        }
    } else {
        model.read_files.push_back(key);
        texture.image = read_image(key);
    }
    reading.bytes += double(texture.image.pixels.size());
    reading.held.set(reading.bytes);
    model.textures.push_back(std::move(texture));
    return reading.decoded[key] = int(model.textures.size()) - 1;
}

// assimp allocates whatever a header claims: while it reads, the address
// space may grow by this much only, so a claim of 10^9 vertices in a 170-byte
// file becomes std::bad_alloc, which assimp reports, instead of exhausting the machine; never more than
// the memory budget (--max-memory).
std::size_t address_space_allowance(std::size_t file_bytes) {
    return std::min((std::size_t(2) << 30) + 256 * file_bytes, std::size_t(memory_budget()));
}

// An assimp material as boxlod's: colours, opacity (blended below 1), Phong
// specular terms as glTF's specular-glossiness, and its textures.
Material convert_material(Model& model, TextureReading& textures, const aiMaterial& in) {
    Material material;
    material.name = utf8_or_latin1(in.GetName().C_Str());
    aiColor4D color;
    if (in.Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS ||
        in.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS)
        material.base_color = {color.r, color.g, color.b, color.a};
    float opacity;
    if (in.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS) material.base_color[3] = opacity;
    // OBJ's and FBX's colours may lie beyond [0, 1] (MTL: "increase the reflectivity"); glTF's factors may
    // not.
    material.base_color = material.base_color.cwiseMax(0).cwiseMin(1);
    if (material.base_color[3] < 1)
        material.alpha_mode = AlphaMode::blend;  // assimp has no alpha mode: see-through is blended
    // Phong specular terms, where the format states them, go out as glTF's specular-glossiness.
    aiColor3D specular;
    if (in.Get(AI_MATKEY_COLOR_SPECULAR, specular) == AI_SUCCESS) {
        material.specular_color = Eigen::Vector3f(specular.r, specular.g, specular.b).cwiseMax(0).cwiseMin(1);
        material.specular_glossiness = true;
    }
    float shininess;
    if (in.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && shininess > 0) material.shininess = shininess;
    int two_sided;
    if (in.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS) material.double_sided = two_sided != 0;
    material.base_color_texture = load_texture(model, textures, in, aiTextureType_BASE_COLOR);
    if (material.base_color_texture < 0)
        material.base_color_texture = load_texture(model, textures, in, aiTextureType_DIFFUSE);
    material.normal_texture = load_texture(model, textures, in, aiTextureType_NORMALS);
    material.specular_texture = load_texture(model, textures, in, aiTextureType_SPECULAR);
    if (material.specular_texture >= 0) material.specular_glossiness = true;
    return material;
}

// The node tree with each node's meshes in world space; a mesh that several
// nodes use names them as instances of it.
void add_nodes(Model& model, const aiScene& scene) {
    std::vector<int> mesh_users(scene.mNumMeshes, 0);
    struct Visit {
        const aiNode* node;
        int parent;
        Eigen::Matrix4d parent_world;
    };
    std::vector<Visit> stack{{scene.mRootNode, -1, Eigen::Matrix4d::Identity()}};
    std::vector<std::pair<int, unsigned>> node_meshes;  // (boxlod node, assimp mesh)
    while (!stack.empty()) {
        Visit visit = stack.back();
        stack.pop_back();
        Eigen::Matrix4d world = visit.parent_world * to_eigen(visit.node->mTransformation);
        int index = add_node(model, visit.parent, utf8_or_latin1(visit.node->mName.C_Str()));
        for (unsigned m = 0; m < visit.node->mNumMeshes; ++m) {
            unsigned mesh = visit.node->mMeshes[m];
            ++mesh_users[mesh];
            node_meshes.emplace_back(index, mesh);
            Primitive primitive = convert_mesh(*scene.mMeshes[mesh], world);
            if (!primitive.indices.empty()) model.nodes[index].primitives.push_back(std::move(primitive));
        }
        for (unsigned c = visit.node->mNumChildren; c-- > 0;)
            stack.push_back({visit.node->mChildren[c], index, world});
    }
    for (auto [node, mesh] : node_meshes)
        if (mesh_users[mesh] > 1) {
            std::string name = utf8_or_latin1(scene.mMeshes[mesh]->mName.C_Str());
            model.nodes[node].instance_of = name.empty() ? "mesh " + std::to_string(mesh) : name;
        }
}

}  // namespace

Model import_with_assimp(const std::string& path) {
    const std::size_t file_bytes = check_input_file(path, "model file");
    // A minute, and a second more per megabyte: many times what assimp takes (docs/performance.md: Reading
    // IFC).
    const ChildLimits limits{address_space_allowance(file_bytes), 60 + double(file_bytes) / 1e6};
    return model_from_bytes(run_in_child([&] { return model_bytes(import_with_assimp_in_process(path)); },
                                         limits, path, "assimp's importer"));
}

Model import_with_assimp_in_process(const std::string& path) {
    std::string bytes = read_input_file(path, "model file");
    const std::string extension = lowercase_extension(path);
    check_assimp_input(bytes, extension, path);
    Assimp::Importer importer;
    // No triangulation here (see convert_mesh); validation rejects inconsistent
    // data; textures mapped by projection (LightWave's planar, cylindrical and
    // spherical mappings) get the texture coordinates a glTF texture needs.
    // From the path: OBJ and others read files beside it.
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure | aiProcess_GenUVCoords);
    if (!scene || !scene->mRootNode) {
        std::string reason = importer.GetErrorString();
        if (reason.find("bad_alloc") != std::string::npos)
            reason = "it would need more than " +
                     std::to_string(address_space_allowance(bytes.size()) >> 20) + " MiB for a " +
                     std::to_string(bytes.size()) +
                     "-byte file (counts in the file too large, or --max-memory too small?)";
        else if (reason.starts_with("std::"))  // a bare C++ exception from deep in a reader
            reason = "malformed " + extension.substr(1) + " file (" + reason + ")";
        throw_input_error(path, "", reason.empty() ? "cannot read model" : "cannot read model: " + reason);
    }
    Model model;
    model.source = path;
    TextureReading textures{*scene, fs::path(path).parent_path(), {}, 0, MemoryHold()};
    for (unsigned i = 0; i < scene->mNumMaterials; ++i)
        model.materials.push_back(convert_material(model, textures, *scene->mMaterials[i]));
    add_nodes(model, *scene);
    make_unit_normals_and_tangents(model);
    validate_model(model);
    return model;
}

}  // namespace boxlod
