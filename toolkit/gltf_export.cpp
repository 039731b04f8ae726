// glTF export (toolkit/gltf_io.h): world-space geometry in a few shared
// buffer views, PNG textures encoded in parallel, every file atomically.
#include "toolkit/gltf_io.h"

#include "base/atomic_write.h"
#include "base/parallel.h"
#include "renderer/image.h"
#include "toolkit/gltf_extras.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace boxlod {
namespace {

namespace fs = std::filesystem;

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

    // An accessor of `count` values at `place` (view, offset), the last in the list.
    tinygltf::Accessor& new_accessor(std::pair<int, std::size_t> place, int component_type, std::size_t count, int type) {
        tinygltf::Accessor& accessor = gltf.accessors.emplace_back();
        accessor.bufferView = place.first;
        accessor.byteOffset = place.second;
        accessor.componentType = component_type;
        accessor.count = count;
        accessor.type = type;
        return accessor;
    }

    template <typename Vector>
    int add_accessor(const std::vector<Vector>& values, int type, bool bounds) {
        Stream& stream = sizeof(Vector) == 12 ? vec3 : sizeof(Vector) == 8 ? vec2 : vec4;
        tinygltf::Accessor& accessor = new_accessor(append(stream, values.data(), values.size() * sizeof(Vector)),
                                                    TINYGLTF_COMPONENT_TYPE_FLOAT, values.size(), type);
        if (bounds && !values.empty()) {
            Vector lo = values[0], hi = values[0];
            for (const Vector& v : values) { lo = lo.cwiseMin(v); hi = hi.cwiseMax(v); }
            for (int c = 0; c < lo.size(); ++c) {
                accessor.minValues.push_back(json_number(lo[c]));
                accessor.maxValues.push_back(json_number(hi[c]));
            }
        }
        return int(gltf.accessors.size()) - 1;
    }

    int add_indices(const std::vector<std::uint32_t>& values) {
        new_accessor(append(indices, values.data(), values.size() * 4), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, values.size(),
                     TINYGLTF_TYPE_SCALAR);
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

// The textures as PNG images: in the .glb's buffer, or as files beside a .gltf
// (named after the texture where that makes a plain .png name).
void add_images(Writer& w, const Model& model, const fs::path& target, bool binary, int threads) {
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
                name = target.stem().string() + "_texture_" + std::to_string(i) + ".png";
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
}

void add_materials(Writer& w, const Model& model) {
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
        out.extras = material_extras(material);
        w.gltf.materials.push_back(out);
    }
}

// The nodes in the model's order (the root first), each with its own mesh.
void add_nodes(Writer& w, const Model& model) {
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
        out.extras = node_extras(node);
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
                p.extras = primitive_extras(primitive);
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
}

}  // namespace

void export_gltf(const Model& model, const std::string& path, int threads) {
    validate_model(model);  // nothing is written that boxlod would refuse to read (NaN, no triangles, ...)
    OutputGroup files;  // images, .bin and .gltf: all or none; the .gltf, which names the others, comes last
    fs::path target(path);
    bool binary = target.extension() == ".glb";
    Writer w;
    w.gltf.asset.version = "2.0";
    w.gltf.asset.generator = "boxlod";
    w.gltf.asset.extras = asset_extras(model);
    add_images(w, model, target, binary, threads);
    add_materials(w, model);
    add_nodes(w, model);

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
    std::string bin_name = target.stem().string() + ".bin";
    write_file_atomically((target.parent_path() / bin_name).string(), data);
    writer.WriteGltfSceneToStream(&w.gltf, stream, true, false);
    // The stream writer embeds the buffer as a data URI (the only one: images
    // are files); point it at NAME.bin instead, as text, without parsing the JSON again.
    std::string json = stream.str();
    const std::string data_uri = "\"uri\": \"data:application/octet-stream;base64,";
    std::size_t begin = json.find(data_uri), end = begin == std::string::npos ? begin : json.find('"', begin + data_uri.size());
    if (end == std::string::npos) throw std::logic_error("export_gltf: no buffer data URI in tinygltf's output");
    json.replace(begin, end + 1 - begin, "\"uri\": " + nlohmann::json(bin_name).dump());
    write_text_atomically(path, json);  // tinygltf ends it with a newline
    files.commit();
}

}  // namespace boxlod
