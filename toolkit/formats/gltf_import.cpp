// glTF import (toolkit/formats/gltf_io.h): checked structure first, then tinygltf, then
// every index, count and transform checked as the model is built.
#include "toolkit/formats/gltf_io.h"

#include "base/atomic_write.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/key_values.h"
#include "base/memory_budget.h"
#include "base/parallel.h"
#include "base/utf8.h"
#include "renderer/image.h"
#include "toolkit/formats/gltf_accessor_reader.h"
#include "toolkit/formats/gltf_extras.h"
#include "toolkit/formats/gltf_json.h"
#include "toolkit/formats/gltf_load.h"
#include "toolkit/formats/gltf_structure.h"
#include "toolkit/formats/gltf_texture_transform.h"

#include <tiny_gltf.h>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>

namespace boxlod {
namespace {

namespace fs = std::filesystem;

using Reader = GltfAccessorReader;

// glTF 2.0, 5.25 "node": a 16-number matrix, or translation (3), a unit
// rotation quaternion (4) and scale (3).
Eigen::Matrix4d local_transform(const tinygltf::Node& node, const Reader& reader, const std::string& place) {
    auto sized = [&](const std::vector<double>& v, std::size_t n, const char* what) {
        if (!v.empty() && v.size() != n)
            reader.fail(place, std::string(what) + " must have " + std::to_string(n) + " numbers");
        return !v.empty();
    };
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    if (sized(node.matrix, 16, "matrix")) {
        for (int i = 0; i < 16; ++i) m(i % 4, i / 4) = node.matrix[i];  // column-major
        if (!(m.row(3) - Eigen::RowVector4d(0, 0, 0, 1))
                 .isZero(1e-6))  // 5.25: decomposable to TRS, so affine
            reader.fail(place, "matrix is not affine (its last row is not 0, 0, 0, 1)");
        m.row(3) << 0, 0, 0, 1;  // an exporter's float noise
        return m;
    }
    Eigen::Affine3d t = Eigen::Affine3d::Identity();
    if (sized(node.translation, 3, "translation"))
        t.translate(Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
    if (sized(node.rotation, 4, "rotation")) {
        Eigen::Quaterniond q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        if (!(std::abs(q.norm() - 1) < 1e-3)) reader.fail(place, "rotation is not a unit quaternion");
        t.rotate(q.normalized());
    }
    if (sized(node.scale, 3, "scale")) t.scale(Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]));
    return t.matrix();
}

// Triangle list from a TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN index stream.
std::vector<std::uint32_t> triangle_list(const std::vector<std::uint32_t>& in, int mode) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return in;
    std::vector<std::uint32_t> out;
    for (std::size_t i = 2; i < in.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
            out.insert(out.end(), {in[0], in[i - 1], in[i]});
        else if (i % 2 == 0)
            out.insert(out.end(), {in[i - 2], in[i - 1], in[i]});
        else
            out.insert(out.end(), {in[i - 1], in[i - 2], in[i]});
    }
    return out;
}

// Points and lines have no faces to draw or bake.
bool draws_triangles(const tinygltf::Primitive& primitive) {
    return primitive.mode == TINYGLTF_MODE_TRIANGLES || primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           primitive.mode == TINYGLTF_MODE_TRIANGLE_FAN || primitive.mode == -1;
}

std::size_t read_primitive(const Reader& reader, const tinygltf::Primitive& in, const Eigen::Matrix4d& world,
                           const std::string& place, Node& node) {
    if (!draws_triangles(in)) return 0;
    auto position = in.attributes.find("POSITION");
    if (position == in.attributes.end()) reader.fail(place, "primitive has no POSITION attribute");
    Primitive out;
    Eigen::Matrix3d linear = world.topLeftCorner<3, 3>();
    Eigen::Matrix3d normal_matrix = linear.inverse().transpose();
    bool mirrored = linear.determinant() < 0;
    for (const auto& p : reader.vectors<3>(position->second, place))
        out.positions.push_back((linear * p + world.topRightCorner<3, 1>()).cast<float>());
    std::size_t n = out.positions.size();
    auto attribute = [&](const char* name) {
        auto it = in.attributes.find(name);
        return it == in.attributes.end() ? -1 : it->second;
    };
    auto check_count = [&](std::size_t count, const char* name) {
        if (count != n) reader.fail(place, std::string(name) + " count differs from POSITION count");
    };
    if (int a = attribute("NORMAL"); a >= 0) {
        auto normals = reader.vectors<3>(a, place);
        check_count(normals.size(), "NORMAL");
        for (const auto& v : normals) out.normals.push_back((normal_matrix * v).normalized().cast<float>());
    }
    if (int a = attribute("TEXCOORD_0"); a >= 0) {
        auto uvs = reader.vectors<2>(a, place);
        check_count(uvs.size(), "TEXCOORD_0");
        for (const auto& v : uvs) out.uvs.push_back(v.cast<float>());
    }
    if (int a = attribute("TANGENT"); a >= 0) {
        auto tangents = reader.vectors<4>(a, place);
        check_count(tangents.size(), "TANGENT");
        for (const auto& v : tangents) {
            Eigen::Vector3d t = (linear * v.head<3>()).normalized();
            out.tangents.emplace_back(float(t.x()), float(t.y()), float(t.z()),
                                      float(mirrored ? -v.w() : v.w()));
        }
    }
    std::vector<std::uint32_t> indices;
    if (in.indices >= 0)
        indices = reader.indices(in.indices, place);
    else
        for (std::uint32_t i = 0; i < n; ++i) indices.push_back(i);
    for (std::uint32_t i : indices)
        if (i >= n)
            reader.fail(place, "vertex index " + std::to_string(i) + " out of range (" + std::to_string(n) +
                                   " vertices)");
    out.indices = triangle_list(indices, in.mode == -1 ? TINYGLTF_MODE_TRIANGLES : in.mode);
    if (out.indices.size() % 3 != 0) reader.fail(place, "index count is not a multiple of 3");
    if (mirrored)
        for (std::size_t i = 0; i < out.indices.size(); i += 3)
            std::swap(out.indices[i + 1], out.indices[i + 2]);
    out.polygon_count = out.triangle_count();
    read_primitive_extras(in.extras, {reader.file, place}, out);
    if (in.material >= int(reader.gltf.materials.size())) reader.fail(place, "material index out of range");
    out.material = in.material;
    if (!out.indices.empty()) node.primitives.push_back(std::move(out));  // no triangle: nothing to draw
    return n;
}

// The image a material's texture samples (-1: none); boxlod reads TEXCOORD_0 only.
int texture_image(const Reader& reader, int texture, int tex_coord, const std::string& place) {
    if (texture < 0) return -1;
    if (tex_coord != 0)
        reader.fail(place, "a texture read with TEXCOORD_" + std::to_string(tex_coord) +
                               " (boxlod reads TEXCOORD_0 only)");
    if (texture >= int(reader.gltf.textures.size())) reader.fail(place, "texture index out of range");
    int source = reader.gltf.textures[texture].source;
    if (source < 0 || source >= int(reader.gltf.images.size()))
        reader.fail(place, "texture has no valid image");
    return source;
}

// `height_map`: the image serves only as a height texture, so a 16-bit grey
// image keeps its 16 bits; as colour or normals it becomes 8-bit grey.
Texture convert_image(const tinygltf::Image& in, bool height_map, const Reader& reader,
                      const std::string& place) {
    if (in.image.empty() || in.width <= 0 || in.height <= 0)
        reader.fail(place, "image '" + in.uri + "' could not be loaded");
    Texture texture;
    texture.name = in.uri.empty() ? in.name : fs::path(file_name_of_uri(in.uri)).filename().string();
    if (in.bits == 8) {
        texture.image = Image8(in.width, in.height, 4);
        texture.image.pixels = in.image;
        return texture;
    }
    Image16 grey(in.width, in.height, 1);
    for (std::size_t i = 0; i < grey.pixels.size(); ++i)
        grey.pixels[i] = std::uint16_t(in.image[i * 2] | in.image[i * 2 + 1] << 8);
    if (height_map) {
        texture.image16 = std::move(grey);
        return texture;
    }
    texture.image = Image8(in.width, in.height, 4, 255);
    for (std::size_t i = 0; i < grey.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            texture.image.pixels[i * 4 + std::size_t(c)] = std::uint8_t(grey.pixels[i] >> 8);
    return texture;
}

// The material extensions boxlod keeps: specular-glossiness and KHR_materials_specular.
void read_material_extensions(const Reader& reader, const tinygltf::Material& in, const std::string& place,
                              Material& material) {
    auto texture = [&](int index, const tinygltf::Value& info) {
        return texture_image(reader, index, tex_coord_read(info), place);
    };
    if (auto extension = in.extensions.find(specular_glossiness_name); extension != in.extensions.end())
        read_specular_glossiness(extension->second, {reader.file, place}, texture, material);
    if (auto extension = in.extensions.find(specular_extension_name); extension != in.extensions.end())
        material.specular_extension =
            read_specular_extension(extension->second, {reader.file, place}, texture);
}

// One texture per image; an image that is only a height map keeps 16 bits.
void read_textures(const Reader& reader, Model& model) {
    const tinygltf::Model& gltf = reader.gltf;
    std::vector<bool> colour_or_normal(gltf.images.size(), false);
    for (std::size_t t = 0; t < gltf.textures.size(); ++t)
        if (gltf.textures[t].sampler >= int(gltf.samplers.size()))
            reader.fail("texture " + std::to_string(t), "sampler index out of range");
    for (std::size_t s = 0; s < gltf.samplers.size(); ++s)  // glTF 2.0, 5.26: the three wrapping modes
        for (const int wrap : {gltf.samplers[s].wrapS, gltf.samplers[s].wrapT})
            if (wrap != TINYGLTF_TEXTURE_WRAP_REPEAT && wrap != TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE &&
                wrap != TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT)
                reader.fail("sampler " + std::to_string(s),
                            "wrap mode " + std::to_string(wrap) + " is not 33071, 33648 or 10497");
    for (std::size_t m = 0; m < gltf.materials.size(); ++m) {
        const std::string place = "material " + std::to_string(m);
        const tinygltf::Material& material = gltf.materials[m];
        for (const auto& [texture, tex_coord] :
             {std::pair{material.pbrMetallicRoughness.baseColorTexture.index,
                        tex_coord_read(material.pbrMetallicRoughness.baseColorTexture.texCoord,
                                       material.pbrMetallicRoughness.baseColorTexture.extensions)},
              std::pair{material.normalTexture.index,
                        tex_coord_read(material.normalTexture.texCoord, material.normalTexture.extensions)}})
            if (int image = texture_image(reader, texture, tex_coord, place); image >= 0)
                colour_or_normal[std::size_t(image)] = true;
        Material extensions;  // only for the images they name, all 8-bit
        read_material_extensions(reader, gltf.materials[m], place, extensions);
        for (const auto& slot : texture_slots(std::as_const(extensions)))
            if (slot.index >= 0) colour_or_normal[std::size_t(slot.index)] = true;
    }
    const auto read_file = [&](const std::string& uri) {  // a file's, not a data URI's
        if (!uri.empty() && !tinygltf::IsDataURI(uri))    // (tinygltf keeps an image's data URI as none)
            model.read_files.push_back(
                (fs::path(reader.file).parent_path() / file_name_of_uri(uri)).string());
    };
    for (std::size_t i = 0; i < gltf.images.size(); ++i) {
        model.textures.push_back(
            convert_image(gltf.images[i], !colour_or_normal[i], reader, "image " + std::to_string(i)));
        read_file(gltf.images[i].uri);
    }
    for (const tinygltf::Buffer& buffer : gltf.buffers) read_file(buffer.uri);
    for (const tinygltf::Texture& texture :
         gltf.textures)  // an image sampled clamped to its edge (LoD pages)
        if (texture.source >= 0 && texture.source < int(gltf.images.size()) && texture.sampler >= 0 &&
            texture.sampler < int(gltf.samplers.size()) &&
            gltf.samplers[texture.sampler].wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE)
            model.textures[std::size_t(texture.source)].wrap = Wrap::clamp;
}

void read_materials(const Reader& reader, Model& model) {
    const tinygltf::Model& gltf = reader.gltf;
    for (std::size_t i = 0; i < gltf.materials.size(); ++i) {
        const tinygltf::Material& in = gltf.materials[i];
        std::string place = "material " + std::to_string(i);
        Material material;
        material.name = in.name;
        const auto& factor = in.pbrMetallicRoughness.baseColorFactor;
        if (factor.size() == 4)
            material.base_color = Eigen::Vector4d(factor[0], factor[1], factor[2], factor[3]).cast<float>();
        const auto& base = in.pbrMetallicRoughness.baseColorTexture;
        material.base_color_texture =
            texture_image(reader, base.index, tex_coord_read(base.texCoord, base.extensions), place);
        material.normal_texture =
            texture_image(reader, in.normalTexture.index,
                          tex_coord_read(in.normalTexture.texCoord, in.normalTexture.extensions), place);
        material.double_sided = in.doubleSided;
        if (!parse_enum(alpha_modes(), in.alphaMode, material.alpha_mode))
            reader.fail(place,
                        "alphaMode '" + in.alphaMode + "' is not " + enum_names(alpha_modes(), ", ", " or "));
        if (!alpha_cutoff_range.contains(in.alphaCutoff))
            reader.fail(place, "alphaCutoff " +
                                   out_of_range_message(alpha_cutoff_range, std::to_string(in.alphaCutoff)));
        material.alpha_cutoff = float(in.alphaCutoff);
        read_material_extensions(reader, in, place, material);
        read_material_extras(in.extras, int(gltf.images.size()), {reader.file, place}, material);
        model.materials.push_back(material);
    }
}

// The default scene's nodes, else every node that is nobody's child.
std::vector<int> scene_roots(const Reader& reader) {
    const tinygltf::Model& gltf = reader.gltf;
    std::vector<int> roots;
    int scene = gltf.defaultScene >= 0 ? gltf.defaultScene : (gltf.scenes.empty() ? -1 : 0);
    if (scene >= int(gltf.scenes.size())) reader.fail("", "default scene out of range");
    if (scene >= 0)
        roots = gltf.scenes[scene].nodes;
    else {
        std::vector<bool> is_child(gltf.nodes.size());
        for (const auto& node : gltf.nodes)
            for (int child : node.children)
                if (child >= 0 && child < int(gltf.nodes.size())) is_child[child] = true;
        for (std::size_t i = 0; i < gltf.nodes.size(); ++i)
            if (!is_child[i]) roots.push_back(int(i));
    }
    if (roots.empty()) reader.fail("", "the scene has no nodes");
    return roots;
}

// A root that boxlod wrote to carry Model::origin: its translation is kept
// as the origin, not applied to the float geometry, and its children are the roots.
std::vector<int> take_origin(const Reader& reader, std::vector<int> roots, Model& model) {
    if (roots.size() != 1 || roots[0] < 0 || roots[0] >= int(reader.gltf.nodes.size())) return roots;
    const tinygltf::Node& node = reader.gltf.nodes[std::size_t(roots[0])];
    if (!is_origin_node(node)) return roots;
    model.origin = Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]);
    if (!model.origin.allFinite())
        reader.fail("node " + std::to_string(roots[0]), "origin translation is NaN or infinite");
    if (node.children.empty())
        reader.fail("node " + std::to_string(roots[0]), "origin node without children");
    model.reference_system =
        read_origin_reference_system(node, {reader.file, "node " + std::to_string(roots[0])});
    return node.children;
}

// Visits the node trees under `roots` depth-first, parents before children, with each node's world matrix:
// visit(n, node, world, parent) returns what its children get as `parent`. An explicit stack, so that a
// deep chain cannot overflow; a node index out of range or a node reached twice (a cycle, or a node shared,
// which glTF 2.0 section 3.5.3 forbids) is refused.
template <class Visit>
void walk_nodes(const Reader& reader, const std::vector<int>& roots, const Eigen::Matrix4d& roots_world,
                int roots_parent, Visit visit) {
    const tinygltf::Model& gltf = reader.gltf;
    struct Pending {
        int gltf_node;
        int parent;
        Eigen::Matrix4d parent_world;
    };
    std::vector<Pending> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.push_back({*it, roots_parent, roots_world});
    std::vector<char> reached(gltf.nodes.size(), 0);
    while (!stack.empty()) {
        const Pending pending = stack.back();
        stack.pop_back();
        const int n = pending.gltf_node;
        const std::string place = "node " + std::to_string(n);
        if (n < 0 || n >= int(gltf.nodes.size())) reader.fail(place, "node index out of range");
        if (reached[std::size_t(n)])
            reader.fail(place, "node appears twice in the hierarchy (cycle or shared node)");
        reached[std::size_t(n)] = 1;
        const tinygltf::Node& node = gltf.nodes[std::size_t(n)];
        const Eigen::Matrix4d world = pending.parent_world * local_transform(node, reader, place);
        if (!world.allFinite()) reader.fail(place, "transform is NaN or infinite");
        const int parent = visit(n, node, world, pending.parent);
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back({*child, parent, world});
    }
}

// The bounds of mesh m's drawn positions, in its own coordinates (non-finite ones left to validate_model);
// each accessor is read once, however many primitives share it.
Eigen::AlignedBox3d position_bounds(const Reader& reader, int m, const std::string& place,
                                    std::map<int, Eigen::AlignedBox3d>& accessor_bounds) {
    Eigen::AlignedBox3d bounds;
    const tinygltf::Mesh& mesh = reader.gltf.meshes[std::size_t(m)];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        auto position = mesh.primitives[p].attributes.find("POSITION");
        if (!draws_triangles(mesh.primitives[p]) || position == mesh.primitives[p].attributes.end()) continue;
        auto [known, added] = accessor_bounds.try_emplace(position->second);
        if (added) {
            const std::string at = place + " mesh " + std::to_string(m) + " primitive " + std::to_string(p);
            for (const Eigen::Vector3d& point : reader.vectors<3>(position->second, at))
                if (point.allFinite()) known->second.extend(point);
        }
        if (!known->second.isEmpty()) bounds.extend(known->second);
    }
    return bounds;
}

// What a model far from its file's (0, 0, 0) is read relative to, as a georeferenced IFC file is
// (docs/design.md: Files): the middle of its bounds in whole units when it lies more than 10 km away,
// so that float keeps millimetres; else (0, 0, 0). Chain level 0's roots give it, so that every level
// of a chain shares it.
Eigen::Vector3d local_origin(const Reader& reader, const std::vector<int>& roots) {
    const tinygltf::Model& gltf = reader.gltf;
    std::vector<std::optional<Eigen::AlignedBox3d>> mesh_bounds(gltf.meshes.size());
    std::map<int, Eigen::AlignedBox3d> accessor_bounds;
    Eigen::AlignedBox3d bounds;
    walk_nodes(reader, roots, Eigen::Matrix4d::Identity(), -1,
               [&](int n, const tinygltf::Node& node, const Eigen::Matrix4d& world, int) {
                   if (node.mesh < 0 || node.mesh >= int(gltf.meshes.size()))
                       return -1;  // read_nodes says why
                   std::optional<Eigen::AlignedBox3d>& local = mesh_bounds[std::size_t(node.mesh)];
                   if (!local)
                       local =
                           position_bounds(reader, node.mesh, "node " + std::to_string(n), accessor_bounds);
                   for (int c = 0; c < 8 && !local->isEmpty(); ++c)
                       bounds.extend(world.topLeftCorner<3, 3>() *
                                         local->corner(Eigen::AlignedBox3d::CornerType(c)) +
                                     world.topRightCorner<3, 1>());
                   return -1;
               });
    const Eigen::Vector3d middle =
        bounds.isEmpty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(bounds.center());
    if (!(middle.allFinite() && (middle.array().abs() <= coordinate_range.max).all()))
        reader.fail("scene", "its middle lies at (" + format_number(middle.x()) + ", " +
                                 format_number(middle.y()) + ", " + format_number(middle.z()) +
                                 "), outside " + range_text(coordinate_range));
    return middle.norm() > 1e4 ? Eigen::Vector3d(middle.array().round()) : Eigen::Vector3d::Zero();
}

// Level K of a chain: the scene's one root, or the K-th of its MSFT_lod.ids.
std::vector<int> chain_level_roots(const Reader& reader, const std::vector<int>& roots, int chain_level) {
    if (chain_level == 0) return roots;
    const std::string place = "level " + std::to_string(chain_level);
    const tinygltf::Value* ids = nullptr;
    if (roots.size() == 1 && roots[0] >= 0 && roots[0] < int(reader.gltf.nodes.size())) {
        const auto& extensions = reader.gltf.nodes[std::size_t(roots[0])].extensions;
        auto lod = extensions.find("MSFT_lod");
        if (lod != extensions.end() && lod->second.Has("ids") && lod->second.Get("ids").IsArray())
            ids = &lod->second.Get("ids");
    }
    if (!ids)
        reader.fail(place,
                    "not an LoD chain: the scene's root has no MSFT_lod ids (build --chain writes them)");
    if (chain_level > int(ids->ArrayLen()))
        reader.fail(place, "the chain has levels 0.." + std::to_string(ids->ArrayLen()));
    const tinygltf::Value& id = ids->Get(chain_level - 1);
    if (!id.IsInt() || id.GetNumberAsInt() < 0 || id.GetNumberAsInt() >= int(reader.gltf.nodes.size()))
        reader.fail(place, "MSFT_lod id is not a node index");
    return {id.GetNumberAsInt()};
}

// What a primitive asks as it is read: the struct and its five allocations (glibc's bookkeeping and
// rounding, about 32 bytes each), 48 bytes a vertex read (positions, normals, uvs, tangents) and 4 an index
// kept. A mesh used by many nodes is read for each, and one accessor may serve many primitives (points,
// lines and primitives without a triangle too), so what a file asks grows faster than its size.
double primitive_memory(std::size_t vertices_read, std::size_t indices_kept) {
    return double(sizeof(Primitive) + 5 * 32) + 48 * double(vertices_read) + 4 * double(indices_kept);
}

// Mesh m's primitives, in world space, into `node`; `memory` counts what the file's meshes hold so far.
void read_mesh(const Reader& reader, int m, const Eigen::Matrix4d& world, const std::string& place,
               Node& node, double& memory) {
    const tinygltf::Mesh& mesh = reader.gltf.meshes[std::size_t(m)];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const std::size_t kept = node.primitives.size();
        const std::size_t vertices =
            read_primitive(reader, mesh.primitives[p], world,
                           place + " mesh " + std::to_string(m) + " primitive " + std::to_string(p), node);
        memory += primitive_memory(vertices,
                                   node.primitives.size() > kept ? node.primitives.back().indices.size() : 0);
        check_memory(reader.file + ": its nodes' meshes, as read", memory);
    }
}

// The node tree under the roots (several roots get a common one, named after
// the file), geometry in world space, parents before children (walk_nodes).
void read_nodes(const Reader& reader, const std::vector<int>& roots, const Eigen::Vector3d& origin,
                Model& model) {
    const tinygltf::Model& gltf = reader.gltf;
    // Meshes used by more than one node of the scene are instances (the nodes
    // a file keeps outside it, such as MSFT_lod's coarser levels, do not count).
    std::vector<int> mesh_users(gltf.meshes.size(), 0);
    walk_nodes(reader, roots, Eigen::Matrix4d::Identity(), -1,
               [&](int, const tinygltf::Node& node, const Eigen::Matrix4d&, int) {
                   if (node.mesh >= 0 && node.mesh < int(gltf.meshes.size()))
                       ++mesh_users[std::size_t(node.mesh)];
                   return -1;
               });
    if (roots.size() > 1) add_node(model, -1, utf8_or_latin1(fs::path(reader.file).stem().string()));
    Eigen::Matrix4d relative_to_origin = Eigen::Matrix4d::Identity();
    relative_to_origin.topRightCorner<3, 1>() = -origin;
    double meshes_memory = 0;
    walk_nodes(reader, roots, relative_to_origin, roots.size() > 1 ? 0 : -1,
               [&](int n, const tinygltf::Node& in, const Eigen::Matrix4d& world, int parent) {
                   const std::string place = "node " + std::to_string(n);
                   const int index = add_node(model, parent, in.name);
                   Node& node = model.nodes[std::size_t(index)];
                   if (in.mesh >= int(gltf.meshes.size())) reader.fail(place, "mesh index out of range");
                   if (in.skin >= int(gltf.skins.size())) reader.fail(place, "skin index out of range");
                   if (in.camera >= int(gltf.cameras.size())) reader.fail(place, "camera index out of range");
                   if (in.mesh >= 0) {
                       read_mesh(reader, in.mesh, world, place, node, meshes_memory);
                       const tinygltf::Mesh& mesh = gltf.meshes[std::size_t(in.mesh)];
                       if (mesh_users[std::size_t(in.mesh)] > 1)
                           node.instance_of =
                               mesh.name.empty() ? "mesh " + std::to_string(in.mesh) : mesh.name;
                   }
                   read_node_extras(in.extras, {reader.file, place}, node);
                   return index;
               });
}

}  // namespace

Model import_gltf(const std::string& path, int chain_level) {
    const bool binary = fs::path(path).extension() == ".glb";
    return import_gltf_bytes(read_input_file(path, binary ? "glb file" : "glTF file"), binary, path,
                             chain_level);
}

// The steps: the structure checked, tinygltf's model, textures, materials, the LoD mark, nodes; validation.
Model import_gltf_bytes(std::string_view bytes, bool binary, const std::string& path, int chain_level) {
    check_gltf_structure(bytes, binary, path);
    const tinygltf::Model gltf = load_gltf(bytes, binary, path);
    Reader reader{gltf, path};
    Model model;
    model.source = path;
    read_textures(reader, model);
    read_materials(reader, model);
    read_asset_extras(gltf.asset.extras, model);
    const std::vector<int> roots = take_origin(reader, scene_roots(reader), model);
    const Eigen::Vector3d origin = local_origin(reader, chain_level_roots(reader, roots, 0));
    read_nodes(reader, chain_level_roots(reader, roots, chain_level), origin, model);
    model.origin += origin;
    place_texture_coordinates(gltf, path, model);
    make_unit_normals_and_tangents(model);
    validate_model(model);
    return model;
}

}  // namespace boxlod
