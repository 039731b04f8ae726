#include "toolkit/gltf_io.h"

#include "base/atomic_write.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/key_values.h"
#include "base/parallel.h"
#include "renderer/image.h"
#include "toolkit/gltf_structure.h"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>

namespace boxlod {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------- import

struct Reader {
    const tinygltf::Model& gltf;
    const std::string& file;

    [[noreturn]] void fail(const std::string& place, const std::string& what) const {
        throw_input_error(file, place, what);
    }

    // Bytes of accessor `index`, checked against its buffer view and buffer.
    struct View {
        const unsigned char* data;
        std::size_t stride, count;
        int component_type, components;
        bool normalized;
    };
    View view(int index, const std::string& place) const {
        if (index < 0 || index >= int(gltf.accessors.size()))
            fail(place, "accessor " + std::to_string(index) + " out of range");
        const tinygltf::Accessor& accessor = gltf.accessors[index];
        std::string where = place + " accessor " + std::to_string(index);
        if (accessor.sparse.isSparse) fail(where, "sparse accessors are not supported");
        if (accessor.bufferView < 0 || accessor.bufferView >= int(gltf.bufferViews.size()))
            fail(where, "buffer view out of range");
        const tinygltf::BufferView& buffer_view = gltf.bufferViews[accessor.bufferView];
        if (buffer_view.buffer < 0 || buffer_view.buffer >= int(gltf.buffers.size())) fail(where, "buffer out of range");
        const tinygltf::Buffer& buffer = gltf.buffers[buffer_view.buffer];
        int component_size = tinygltf::GetComponentSizeInBytes(accessor.componentType);
        int components = tinygltf::GetNumComponentsInType(accessor.type);
        if (component_size <= 0 || components <= 0) fail(where, "unknown component or element type");
        std::size_t element = std::size_t(component_size) * components;
        std::size_t stride = buffer_view.byteStride ? buffer_view.byteStride : element;
        if (stride < element) fail(where, "byteStride is smaller than an element");
        // Every size here comes from the file: checked against overflow before it is added.
        std::size_t needed = 0;
        if (accessor.count > 0 && (!checked_multiply(accessor.count - 1, stride, needed) || needed > SIZE_MAX - element))
            fail(where, "count " + std::to_string(accessor.count) + " is larger than any buffer");
        if (accessor.count > 0) needed += element;
        if (!range_fits(buffer_view.byteOffset, buffer_view.byteLength, buffer.data.size()) ||
            !range_fits(accessor.byteOffset, needed, buffer_view.byteLength))
            fail(where, "data runs past the end of its buffer (truncated file?)");
        return {buffer.data.data() + buffer_view.byteOffset + accessor.byteOffset, stride, accessor.count, accessor.componentType,
                components, accessor.normalized};
    }

    static double component(const unsigned char* p, int type, bool normalized) {
        switch (type) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: { float v; std::memcpy(&v, p, 4); return v; }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0 : *p;
            case TINYGLTF_COMPONENT_TYPE_BYTE: { auto v = double(std::int8_t(*p)); return normalized ? std::max(v / 127.0, -1.0) : v; }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t v; std::memcpy(&v, p, 2); return normalized ? v / 65535.0 : v; }
            case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t v; std::memcpy(&v, p, 2); return normalized ? std::max(v / 32767.0, -1.0) : v; }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
            default: return 0;
        }
    }

    template <int N>
    std::vector<Eigen::Matrix<double, N, 1>> vectors(int index, const std::string& place) const {
        View v = view(index, place);
        if (v.components != N) fail(place + " accessor " + std::to_string(index), "expected " + std::to_string(N) + " components");
        int size = tinygltf::GetComponentSizeInBytes(v.component_type);
        std::vector<Eigen::Matrix<double, N, 1>> out(v.count);
        for (std::size_t i = 0; i < v.count; ++i)
            for (int c = 0; c < N; ++c) out[i][c] = component(v.data + i * v.stride + c * size, v.component_type, v.normalized);
        return out;
    }

    std::vector<std::uint32_t> indices(int index, const std::string& place) const {
        View v = view(index, place);
        if (v.components != 1 || !(v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                   v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                   v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
            fail(place, "indices must be unsigned integer scalars");
        int size = tinygltf::GetComponentSizeInBytes(v.component_type);
        std::vector<std::uint32_t> out(v.count);
        for (std::size_t i = 0; i < v.count; ++i)
            out[i] = std::uint32_t(component(v.data + i * v.stride, v.component_type, false));
        (void)size;
        return out;
    }
};

// glTF 2.0, 5.25 "node": a 16-number matrix, or translation (3), a unit
// rotation quaternion (4) and scale (3).
Eigen::Matrix4d local_transform(const tinygltf::Node& node, const Reader& reader, const std::string& place) {
    auto sized = [&](const std::vector<double>& v, std::size_t n, const char* what) {
        if (!v.empty() && v.size() != n) reader.fail(place, std::string(what) + " must have " + std::to_string(n) + " numbers");
        return !v.empty();
    };
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    if (sized(node.matrix, 16, "matrix")) {
        for (int i = 0; i < 16; ++i) m(i % 4, i / 4) = node.matrix[i];  // column-major
        return m;
    }
    Eigen::Affine3d t = Eigen::Affine3d::Identity();
    if (sized(node.translation, 3, "translation")) t.translate(Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
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
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN) out.insert(out.end(), {in[0], in[i - 1], in[i]});
        else if (i % 2 == 0) out.insert(out.end(), {in[i - 2], in[i - 1], in[i]});
        else out.insert(out.end(), {in[i - 1], in[i - 2], in[i]});
    }
    return out;
}

const tinygltf::Value* boxlod_extras(const tinygltf::Value& extras) {
    if (!extras.IsObject() || !extras.Has("boxlod")) return nullptr;
    const tinygltf::Value& v = extras.Get("boxlod");
    return v.IsObject() ? &v : nullptr;
}

template <int N>
Eigen::Matrix<float, N, 1> number_array(const tinygltf::Value& v, const Reader& reader, const std::string& place) {
    Eigen::Matrix<float, N, 1> out;
    if (!v.IsArray() || int(v.ArrayLen()) != N) reader.fail(place, "expected an array of " + std::to_string(N) + " numbers");
    for (int i = 0; i < N; ++i) {
        if (!v.Get(i).IsNumber()) reader.fail(place, "expected a number");
        out[i] = float(v.Get(i).GetNumberAsDouble());
    }
    return out;
}

constexpr float max_scope_extent = 1e6f;

Scope read_scope(const tinygltf::Value& v, const Reader& reader, const std::string& place) {
    if (!v.IsObject()) reader.fail(place, "scope must be an object");
    Scope scope;
    scope.center = number_array<3>(v.Get("center"), reader, place + " scope.center");
    scope.half_extents = number_array<3>(v.Get("half_extents"), reader, place + " scope.half_extents");
    const tinygltf::Value& axes = v.Get("axes");
    if (!axes.IsArray() || axes.ArrayLen() != 3) reader.fail(place, "scope.axes must hold three axes");
    for (int i = 0; i < 3; ++i) scope.axes.col(i) = number_array<3>(axes.Get(i), reader, place + " scope.axes");
    // A scope is an oriented box: orthonormal axes, extents of 0 or more.
    if (!((scope.axes.transpose() * scope.axes - Eigen::Matrix3f::Identity()).cwiseAbs().maxCoeff() < 1e-3f))
        reader.fail(place, "scope.axes must be three orthonormal axes");
    if (!((scope.half_extents.array() >= 0).all() && (scope.half_extents.array() <= max_scope_extent).all()))
        reader.fail(place, "scope.half_extents must be in [0, 1e6]");
    return scope;
}

void read_primitive(const Reader& reader, const tinygltf::Primitive& in, const Eigen::Matrix4d& world,
                    const std::string& place, Node& node) {
    if (in.mode != TINYGLTF_MODE_TRIANGLES && in.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        in.mode != TINYGLTF_MODE_TRIANGLE_FAN && in.mode != -1)
        return;  // points and lines have no faces to render or bake
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
            out.tangents.emplace_back(float(t.x()), float(t.y()), float(t.z()), float(mirrored ? -v.w() : v.w()));
        }
    }
    std::vector<std::uint32_t> indices;
    if (in.indices >= 0) indices = reader.indices(in.indices, place);
    else for (std::uint32_t i = 0; i < n; ++i) indices.push_back(i);
    for (std::uint32_t i : indices)
        if (i >= n) reader.fail(place, "vertex index " + std::to_string(i) + " out of range (" + std::to_string(n) + " vertices)");
    out.indices = triangle_list(indices, in.mode == -1 ? TINYGLTF_MODE_TRIANGLES : in.mode);
    if (out.indices.size() % 3 != 0) reader.fail(place, "index count is not a multiple of 3");
    if (mirrored)
        for (std::size_t i = 0; i < out.indices.size(); i += 3) std::swap(out.indices[i + 1], out.indices[i + 2]);
    out.polygon_count = out.triangle_count();
    if (const tinygltf::Value* extras = boxlod_extras(in.extras); extras && extras->Has("polygons")) {
        const tinygltf::Value& polygons = extras->Get("polygons");
        // Each polygon is at least one triangle.
        if (!polygons.IsNumber() || !(polygons.GetNumberAsDouble() >= 0 && polygons.GetNumberAsDouble() <= double(out.triangle_count())))
            reader.fail(place, "extras.boxlod.polygons must be a count of at most the primitive's triangles");
        out.polygon_count = std::size_t(polygons.GetNumberAsDouble());
    }
    if (in.material >= int(reader.gltf.materials.size())) reader.fail(place, "material index out of range");
    out.material = in.material;
    node.primitives.push_back(std::move(out));
}

int texture_image(const Reader& reader, int texture, const std::string& place) {
    if (texture < 0) return -1;
    if (texture >= int(reader.gltf.textures.size())) reader.fail(place, "texture index out of range");
    int source = reader.gltf.textures[texture].source;
    if (source < 0 || source >= int(reader.gltf.images.size())) reader.fail(place, "texture has no valid image");
    return source;
}

// tinygltf's file callback: buffers and images named by URI are read as every
// input file is (a folder, a device or a missing file is a clear error).
bool read_whole_file(std::vector<unsigned char>* out, std::string*, const std::string& path, void*) {
    std::string bytes = read_input_file(path, "file");
    out->assign(bytes.begin(), bytes.end());
    return true;
}

// tinygltf's image callback: our decoders, so that a broken image is named by
// its own file and a claimed size is checked before anything is allocated.
// 16-bit grey stays 16-bit (height maps); everything else becomes RGBA8.
bool load_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int, const unsigned char* bytes,
                int size, void* gltf_file) {
    const std::string& file = *static_cast<const std::string*>(gltf_file);
    std::string name = image->uri.empty() ? file + ": image " + std::to_string(index)
                                          : (fs::path(file).parent_path() / image->uri).string();
    std::span<const std::uint8_t> encoded(bytes, std::size_t(size));
    if (is_grey16(encoded)) {
        Image16 decoded = decode_image16(encoded, name);
        image->image.resize(decoded.pixels.size() * 2);
        for (std::size_t i = 0; i < decoded.pixels.size(); ++i)
            image->image[i * 2] = std::uint8_t(decoded.pixels[i] & 0xff), image->image[i * 2 + 1] = std::uint8_t(decoded.pixels[i] >> 8);
        image->width = decoded.width, image->height = decoded.height, image->component = 1, image->bits = 16;
        image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    } else {
        Image8 decoded = decode_image(encoded, name);
        image->image = std::move(decoded.pixels);
        image->width = decoded.width, image->height = decoded.height, image->component = 4, image->bits = 8;
        image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    }
    return true;
}

// `height_map`: the image serves only as a height texture, so a 16-bit grey
// image keeps its 16 bits; as colour or normals it becomes 8-bit grey.
Texture convert_image(const tinygltf::Image& in, bool height_map, const Reader& reader, const std::string& place) {
    if (in.image.empty() || in.width <= 0 || in.height <= 0) reader.fail(place, "image '" + in.uri + "' could not be loaded");
    Texture texture;
    texture.name = in.uri.empty() ? in.name : fs::path(in.uri).filename().string();
    if (in.bits == 8) {
        texture.image = Image8(in.width, in.height, 4);
        texture.image.pixels = in.image;
        return texture;
    }
    Image16 grey(in.width, in.height, 1);
    for (std::size_t i = 0; i < grey.pixels.size(); ++i) grey.pixels[i] = std::uint16_t(in.image[i * 2] | in.image[i * 2 + 1] << 8);
    if (height_map) {
        texture.image16 = std::move(grey);
        return texture;
    }
    texture.image = Image8(in.width, in.height, 4, 255);
    for (std::size_t i = 0; i < grey.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) texture.image.pixels[i * 4 + std::size_t(c)] = std::uint8_t(grey.pixels[i] >> 8);
    return texture;
}

}  // namespace

Model import_gltf(const std::string& path) {
    const bool binary = fs::path(path).extension() == ".glb";
    return import_gltf_bytes(read_input_file(path, binary ? "glb file" : "glTF file"), binary, path);
}

Model import_gltf_bytes(std::string_view bytes, bool binary, const std::string& path) {
    check_gltf_structure(bytes, binary, path);
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(load_image, const_cast<std::string*>(&path));
    tinygltf::FsCallbacks files{&tinygltf::FileExists, &tinygltf::ExpandFilePath, &read_whole_file, &tinygltf::WriteWholeFile, nullptr};
    loader.SetFsCallbacks(files);
    tinygltf::Model gltf;
    std::string error, warning, directory = fs::path(path).parent_path().string();
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    bool ok = binary ? loader.LoadBinaryFromMemory(&gltf, &error, &warning, data, unsigned(bytes.size()), directory)
                     : loader.LoadASCIIFromString(&gltf, &error, &warning, bytes.data(), unsigned(bytes.size()), directory);
    if (!ok) throw_input_error(path, "", error.empty() ? "malformed glTF" : error);

    Reader reader{gltf, path};
    Model model;
    model.source = path;
    std::vector<bool> colour_or_normal(gltf.images.size(), false);
    for (std::size_t m = 0; m < gltf.materials.size(); ++m)
        for (int texture : {gltf.materials[m].pbrMetallicRoughness.baseColorTexture.index, gltf.materials[m].normalTexture.index})
            if (int image = texture_image(reader, texture, "material " + std::to_string(m)); image >= 0)
                colour_or_normal[std::size_t(image)] = true;
    for (std::size_t i = 0; i < gltf.images.size(); ++i)
        model.textures.push_back(convert_image(gltf.images[i], !colour_or_normal[i], reader, "image " + std::to_string(i)));
    for (const tinygltf::Texture& texture : gltf.textures)  // an image sampled clamped to its edge (LoD pages)
        if (texture.source >= 0 && texture.source < int(gltf.images.size()) && texture.sampler >= 0 &&
            texture.sampler < int(gltf.samplers.size()) && gltf.samplers[texture.sampler].wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE)
            model.textures[std::size_t(texture.source)].wrap = Wrap::clamp;
    for (std::size_t i = 0; i < gltf.materials.size(); ++i) {
        const tinygltf::Material& in = gltf.materials[i];
        std::string place = "material " + std::to_string(i);
        Material material;
        material.name = in.name;
        const auto& factor = in.pbrMetallicRoughness.baseColorFactor;
        if (factor.size() == 4) material.base_color = Eigen::Vector4d(factor[0], factor[1], factor[2], factor[3]).cast<float>();
        material.base_color_texture = texture_image(reader, in.pbrMetallicRoughness.baseColorTexture.index, place);
        material.normal_texture = texture_image(reader, in.normalTexture.index, place);
        material.double_sided = in.doubleSided;
        material.alpha_cutout = in.alphaMode == "MASK";
        if (const tinygltf::Value* extras = boxlod_extras(in.extras)) {
            if (extras->Has("specular")) material.specular_color = number_array<3>(extras->Get("specular"), reader, place + " specular");
            if (extras->Has("shininess")) material.shininess = float(extras->Get("shininess").GetNumberAsDouble());
            if (extras->Has("height_texture") && extras->Get("height_texture").IsNumber()) {
                int texture = int(extras->Get("height_texture").GetNumberAsDouble());
                if (texture < 0 || texture >= int(gltf.images.size())) reader.fail(place, "height_texture out of range");
                material.height_texture = texture;
            }
        }
        model.materials.push_back(material);
    }
    if (const tinygltf::Value* extras = boxlod_extras(gltf.asset.extras)) {
        model.is_lod = extras->Has("lod") && extras->Get("lod").IsBool() && extras->Get("lod").Get<bool>();
        if (extras->Has("params") && extras->Get("params").IsObject()) {
            const tinygltf::Value& params = extras->Get("params");
            for (const std::string& key : params.Keys())
                model.lod_params.emplace_back(key, params.Get(key).IsString() ? params.Get(key).Get<std::string>() : "");
        }
    }

    // Roots: the default scene's nodes, else every node that is nobody's child.
    std::vector<int> roots;
    int scene = gltf.defaultScene >= 0 ? gltf.defaultScene : (gltf.scenes.empty() ? -1 : 0);
    if (scene >= int(gltf.scenes.size())) reader.fail("", "default scene out of range");
    if (scene >= 0) roots = gltf.scenes[scene].nodes;
    else {
        std::vector<bool> is_child(gltf.nodes.size());
        for (const auto& node : gltf.nodes)
            for (int child : node.children)
                if (child >= 0 && child < int(gltf.nodes.size())) is_child[child] = true;
        for (std::size_t i = 0; i < gltf.nodes.size(); ++i)
            if (!is_child[i]) roots.push_back(int(i));
    }
    if (roots.empty()) reader.fail("", "the scene has no nodes");

    std::vector<int> mesh_users(gltf.meshes.size(), 0);
    for (const auto& node : gltf.nodes)
        if (node.mesh >= 0 && node.mesh < int(gltf.meshes.size())) ++mesh_users[node.mesh];

    // Depth-first, parents before children; an explicit stack so a deep chain cannot overflow.
    struct Visit { int gltf_node; int parent; Eigen::Matrix4d parent_world; };
    std::vector<Visit> stack;
    if (roots.size() > 1) add_node(model, -1, fs::path(path).stem().string());
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.push_back({*it, roots.size() > 1 ? 0 : -1, Eigen::Matrix4d::Identity()});
    std::vector<bool> visited(gltf.nodes.size(), false);
    while (!stack.empty()) {
        Visit visit = stack.back();
        stack.pop_back();
        std::string place = "node " + std::to_string(visit.gltf_node);
        if (visit.gltf_node < 0 || visit.gltf_node >= int(gltf.nodes.size())) reader.fail(place, "node index out of range");
        if (visited[visit.gltf_node]) reader.fail(place, "node appears twice in the hierarchy (cycle or shared node)");
        visited[visit.gltf_node] = true;
        const tinygltf::Node& in = gltf.nodes[visit.gltf_node];
        Eigen::Matrix4d world = visit.parent_world * local_transform(in, reader, place);
        if (!world.allFinite()) reader.fail(place, "transform is NaN or infinite");
        int index = add_node(model, visit.parent, in.name);
        Node& node = model.nodes[index];
        if (in.mesh >= int(gltf.meshes.size())) reader.fail(place, "mesh index out of range");
        if (in.mesh >= 0) {
            const tinygltf::Mesh& mesh = gltf.meshes[in.mesh];
            for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
                read_primitive(reader, mesh.primitives[p], world, place + " mesh " + std::to_string(in.mesh) + " primitive " + std::to_string(p), node);
            if (mesh_users[in.mesh] > 1) node.instance_of = mesh.name.empty() ? "mesh " + std::to_string(in.mesh) : mesh.name;
        }
        if (const tinygltf::Value* extras = boxlod_extras(in.extras)) {
            if (extras->Has("rule") && extras->Get("rule").IsString()) node.rule = extras->Get("rule").Get<std::string>();
            if (extras->Has("scope")) node.scope = read_scope(extras->Get("scope"), reader, place);
            if (extras->Has("instance_of") && extras->Get("instance_of").IsString())
                node.instance_of = extras->Get("instance_of").Get<std::string>();
        }
        for (auto child = in.children.rbegin(); child != in.children.rend(); ++child)
            stack.push_back({*child, index, world});
    }
    validate_model(model);
    return model;
}

// ---------------------------------------------------------------- export
namespace {

// The double nearest to a float's shortest decimal form: JSON prints "0.3", not
// "0.30000001192092896", and reading it back as float gives the same float.
double json_number(float value) { return std::strtod(format_number(value).c_str(), nullptr); }

// Geometry goes into a few shared buffer views (one per element size) rather
// than a view per accessor: a city has hundreds of thousands of accessors, and
// the JSON shrinks by a third. Images get a view each.
struct Writer {
    tinygltf::Model gltf;

    struct Stream {
        int target = 0, stride = 0;
        bool shared = true;  // one view for the whole stream; else a view per piece (images)
        std::vector<unsigned char> bytes;
        std::vector<int> views;  // their byteOffset is relative to this stream until finish()
    };
    Stream vec3{TINYGLTF_TARGET_ARRAY_BUFFER, 12, true, {}, {}}, vec2{TINYGLTF_TARGET_ARRAY_BUFFER, 8, true, {}, {}},
        vec4{TINYGLTF_TARGET_ARRAY_BUFFER, 16, true, {}, {}},
        indices{TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, 0, true, {}, {}}, blobs{0, 0, false, {}, {}};

    int new_view(Stream& stream, std::size_t offset, std::size_t length) {
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = offset;
        view.byteLength = length;
        view.byteStride = std::size_t(stream.stride);
        view.target = stream.target;
        gltf.bufferViews.push_back(view);
        stream.views.push_back(int(gltf.bufferViews.size()) - 1);
        return stream.views.back();
    }

    // Appends bytes; returns (view, offset of the bytes within that view).
    std::pair<int, std::size_t> append(Stream& stream, const void* bytes, std::size_t size) {
        while (stream.bytes.size() % 4) stream.bytes.push_back(0);  // glTF alignment
        std::size_t offset = stream.bytes.size();
        const auto* p = static_cast<const unsigned char*>(bytes);
        stream.bytes.insert(stream.bytes.end(), p, p + size);
        if (!stream.shared) return {new_view(stream, offset, size), 0};
        int view = stream.views.empty() ? new_view(stream, 0, 0) : stream.views.front();
        return {view, offset};
    }

    int add_image(const std::vector<std::uint8_t>& png) { return append(blobs, png.data(), png.size()).first; }

    template <typename Vector>
    int add_accessor(const std::vector<Vector>& values, int type, bool bounds) {
        Stream& stream = sizeof(Vector) == 12 ? vec3 : sizeof(Vector) == 8 ? vec2 : vec4;
        auto [view, offset] = append(stream, values.data(), values.size() * sizeof(Vector));
        tinygltf::Accessor accessor;
        accessor.bufferView = view;
        accessor.byteOffset = offset;
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.count = values.size();
        accessor.type = type;
        if (bounds && !values.empty()) {
            Vector lo = values[0], hi = values[0];
            for (const Vector& v : values) { lo = lo.cwiseMin(v); hi = hi.cwiseMax(v); }
            for (int c = 0; c < lo.size(); ++c) {
                accessor.minValues.push_back(json_number(lo[c]));
                accessor.maxValues.push_back(json_number(hi[c]));
            }
        }
        gltf.accessors.push_back(std::move(accessor));
        return int(gltf.accessors.size()) - 1;
    }

    int add_indices(const std::vector<std::uint32_t>& values) {
        auto [view, offset] = append(indices, values.data(), values.size() * 4);
        tinygltf::Accessor accessor;
        accessor.bufferView = view;
        accessor.byteOffset = offset;
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        accessor.count = values.size();
        accessor.type = TINYGLTF_TYPE_SCALAR;
        gltf.accessors.push_back(std::move(accessor));
        return int(gltf.accessors.size()) - 1;
    }

    // Lays the streams out in one buffer, in a fixed order, and places the views.
    const std::vector<unsigned char>& finish() {
        gltf.buffers.resize(1);
        std::vector<unsigned char>& data = gltf.buffers[0].data;
        for (Stream* stream : {&vec3, &vec2, &vec4, &indices, &blobs}) {
            while (data.size() % 4) data.push_back(0);
            std::size_t base = data.size();
            data.insert(data.end(), stream->bytes.begin(), stream->bytes.end());
            for (int view : stream->views) {
                gltf.bufferViews[view].byteOffset += base;
                if (stream->shared) gltf.bufferViews[view].byteLength = stream->bytes.size();
            }
        }
        return data;
    }
};

tinygltf::Value number_array(const float* values, int n) {
    tinygltf::Value::Array array;
    for (int i = 0; i < n; ++i) array.emplace_back(json_number(values[i]));
    return tinygltf::Value(std::move(array));
}

tinygltf::Value boxlod_object(tinygltf::Value::Object fields) {
    tinygltf::Value::Object extras;
    extras["boxlod"] = tinygltf::Value(std::move(fields));
    return tinygltf::Value(std::move(extras));
}

}  // namespace

void export_gltf(const Model& model, const std::string& path, int threads) {
    validate_model(model);  // nothing is written that boxlod would refuse to read (NaN, no triangles, ...)
    OutputGroup files;  // images, .bin and .gltf: all or none; the .gltf, which names the others, comes last
    fs::path target(path);
    bool binary = target.extension() == ".glb";
    std::string stem = target.stem().string();
    Writer w;
    w.gltf.asset.version = "2.0";
    w.gltf.asset.generator = "boxlod";
    if (model.is_lod) {
        tinygltf::Value::Object params;
        for (const auto& [key, value] : model.lod_params) params[key] = tinygltf::Value(value);
        w.gltf.asset.extras = boxlod_object({{"lod", tinygltf::Value(true)}, {"params", tinygltf::Value(std::move(params))}});
    }

    std::vector<std::string> image_files;
    // PNG encoding dominates an LoD export: encode the textures in parallel, store them in order.
    std::vector<std::vector<std::uint8_t>> encoded(model.textures.size());
    parallel_for(model.textures.size(), threads, [&](std::size_t i) {
        const Texture& texture = model.textures[i];
        encoded[i] = texture.image16.empty() ? encode_png(texture.image) : encode_png16(texture.image16);
    });
    for (std::size_t i = 0; i < model.textures.size(); ++i) {
        const Texture& texture = model.textures[i];
        const std::vector<std::uint8_t>& png = encoded[i];
        tinygltf::Image image;
        image.name = texture.name;
        image.mimeType = "image/png";
        if (binary) {
            image.bufferView = w.add_image(png);
        } else {
            std::string name = fs::path(texture.name).filename().string();
            if (fs::path(name).extension() != ".png" || name.find_first_of("/\\ ") != std::string::npos)
                name = stem + "_texture_" + std::to_string(i) + ".png";
            image.uri = name;
            write_file_atomically((target.parent_path() / name).string(), png);
        }
        w.gltf.images.push_back(image);
        tinygltf::Texture gltf_texture;
        gltf_texture.source = int(i);
        if (texture.wrap == Wrap::clamp) {
            if (w.gltf.samplers.empty()) {
                tinygltf::Sampler clamp;
                clamp.wrapS = clamp.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
                clamp.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
                clamp.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
                w.gltf.samplers.push_back(clamp);
            }
            gltf_texture.sampler = 0;
        }
        w.gltf.textures.push_back(gltf_texture);
    }
    for (const Material& material : model.materials) {
        tinygltf::Material out;
        out.name = material.name;
        out.pbrMetallicRoughness.baseColorFactor.clear();
        for (int c = 0; c < 4; ++c) out.pbrMetallicRoughness.baseColorFactor.push_back(json_number(material.base_color[c]));
        out.pbrMetallicRoughness.baseColorTexture.index = material.base_color_texture;
        out.pbrMetallicRoughness.metallicFactor = 0;
        out.pbrMetallicRoughness.roughnessFactor = 1;
        out.normalTexture.index = material.normal_texture;
        out.doubleSided = material.double_sided;
        if (material.alpha_cutout) out.alphaMode = "MASK";  // cutoff 0.5, the glTF default
        tinygltf::Value::Object extras{{"specular", number_array(material.specular_color.data(), 3)},
                                       {"shininess", tinygltf::Value(json_number(material.shininess))}};
        // glTF has no height-map slot; the image index travels in extras.
        if (material.height_texture >= 0) extras["height_texture"] = tinygltf::Value(material.height_texture);
        out.extras = boxlod_object(std::move(extras));
        w.gltf.materials.push_back(out);
    }
    // tinygltf's types copy (not move) when a vector grows: reserve everything up front.
    std::size_t meshes = 0, primitives = 0;
    for (const Node& node : model.nodes) meshes += node.has_geometry(), primitives += node.primitives.size();
    w.gltf.nodes.reserve(model.nodes.size());
    w.gltf.meshes.reserve(meshes);
    w.gltf.accessors.reserve(primitives * 5);
    for (const Node& node : model.nodes) {
        tinygltf::Node out;
        out.name = node.name;
        out.children = node.children;
        tinygltf::Value::Object extras;
        if (!node.rule.empty()) extras["rule"] = tinygltf::Value(node.rule);
        if (!node.instance_of.empty()) extras["instance_of"] = tinygltf::Value(node.instance_of);
        if (node.scope) {
            tinygltf::Value::Array axes;
            for (int i = 0; i < 3; ++i) {
                Eigen::Vector3f axis = node.scope->axes.col(i);
                axes.push_back(number_array(axis.data(), 3));
            }
            extras["scope"] = tinygltf::Value(tinygltf::Value::Object{
                {"center", number_array(node.scope->center.data(), 3)},
                {"axes", tinygltf::Value(std::move(axes))},
                {"half_extents", number_array(node.scope->half_extents.data(), 3)}});
        }
        if (!extras.empty()) out.extras = boxlod_object(std::move(extras));
        if (node.has_geometry()) {
            tinygltf::Mesh mesh;
            mesh.name = node.name;
            for (const Primitive& primitive : node.primitives) {
                tinygltf::Primitive p;
                p.mode = TINYGLTF_MODE_TRIANGLES;
                p.material = primitive.material;
                p.attributes["POSITION"] = w.add_accessor(primitive.positions, TINYGLTF_TYPE_VEC3, true);
                if (!primitive.normals.empty()) p.attributes["NORMAL"] = w.add_accessor(primitive.normals, TINYGLTF_TYPE_VEC3, false);
                if (!primitive.uvs.empty()) p.attributes["TEXCOORD_0"] = w.add_accessor(primitive.uvs, TINYGLTF_TYPE_VEC2, false);
                if (!primitive.tangents.empty()) p.attributes["TANGENT"] = w.add_accessor(primitive.tangents, TINYGLTF_TYPE_VEC4, false);
                p.indices = w.add_indices(primitive.indices);
                if (primitive.polygon_count != primitive.triangle_count())
                    p.extras = boxlod_object({{"polygons", tinygltf::Value(int(primitive.polygon_count))}});
                mesh.primitives.push_back(p);
            }
            w.gltf.meshes.push_back(std::move(mesh));
            out.mesh = int(w.gltf.meshes.size()) - 1;
        }
        w.gltf.nodes.push_back(std::move(out));
    }
    tinygltf::Scene scene;
    scene.nodes = {0};
    w.gltf.scenes.push_back(scene);
    w.gltf.defaultScene = 0;

    const std::vector<unsigned char>& data = w.finish();
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(nullptr, nullptr);  // images are written above, atomically
    std::ostringstream stream;
    if (binary) {
        writer.WriteGltfSceneToStream(&w.gltf, stream, false, true);
        write_text_atomically(path, stream.str());
        files.commit();
        return;
    }
    std::string bin_name = stem + ".bin";
    write_file_atomically((target.parent_path() / bin_name).string(), data);
    writer.WriteGltfSceneToStream(&w.gltf, stream, true, false);
    // The stream writer embeds buffers as data URIs; point the buffer at NAME.bin instead.
    nlohmann::json json = nlohmann::json::parse(stream.str());
    json["buffers"][0] = {{"byteLength", data.size()}, {"uri", bin_name}};
    write_text_atomically(path, json.dump(2) + "\n");
    files.commit();
}

}  // namespace boxlod
