// The glTF document of a model or a chain (toolkit/formats/gltf_document.h):
// world-space geometry in a few shared buffer views, PNG textures encoded in
// parallel, equal textures, materials and meshes of a chain's levels once.
#include "toolkit/formats/gltf_document.h"

#include "base/atomic_write.h"
#include "base/parallel.h"
#include "renderer/image.h"
#include "toolkit/formats/gltf_extras.h"
#include "toolkit/formats/gltf_json.h"
#include "toolkit/model/vertex_layout.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include <sys/stat.h>
#include <unordered_map>

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
    // Where the model being added lands: its texture i is glTF texture textures[i],
    // its material i glTF material materials[i], its node 0 node_offset.
    std::vector<int> textures, materials;
    // ... and glTF material untextured_materials[i] where drawn without its
    // textures (drawn_untextured); the same as materials[i] where it is only so or never.
    std::vector<int> untextured_materials;
    int node_offset = 0;
    // A chain's levels share what is equal: textures by content, materials, and
    // the geometry of the parts a level keeps (its nodes and meshes stay its own).
    bool share = false;
    std::map<TextureDigest, int> texture_of;
    struct WrittenMesh {
        const Node* node;            // whose primitives it holds
        std::vector<int> materials;  // their glTF materials
        int mesh;
    };
    std::unordered_multimap<std::uint64_t, WrittenMesh> meshes;
    // Babylon.js disposes a level's meshes, and their instances, when the next
    // level replaces it: a level's nodes use glTF meshes of its own, copies
    // that share the accessors of a mesh an earlier level wrote.
    std::map<int, int> level_copies;                        // a mesh of an earlier level -> this level's copy
    std::vector<int> level_meshes_begin;                    // level k's meshes: [begin[k], begin[k + 1])
    std::vector<std::vector<unsigned char>> level_buffers;  // buffers 1.. (see sequence_levels)
    std::set<std::string> image_files;                      // .gltf: the PNG names taken
    std::set<std::pair<dev_t, ino_t>> read_files;           // the files the levels were read with

    Stream vec3{TINYGLTF_TARGET_ARRAY_BUFFER, 12, true, {}, {}},
        vec2{TINYGLTF_TARGET_ARRAY_BUFFER, 8, true, {}, {}},
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

    // Appends bytes at a multiple of `alignment` (glTF: an accessor's offset is a
    // multiple of its component size; 4 keeps floats aligned); returns (view, offset of the bytes within that
    // view).
    std::pair<int, std::size_t> append(Stream& stream, const void* bytes, std::size_t size,
                                       std::size_t alignment = 4) {
        while (stream.bytes.size() % alignment) stream.bytes.push_back(0);
        std::size_t offset = stream.bytes.size();
        const auto* p = static_cast<const unsigned char*>(bytes);
        stream.bytes.insert(stream.bytes.end(), p, p + size);
        if (!stream.shared) return {new_view(stream, offset, size), 0};
        int view = stream.views.empty() ? new_view(stream, 0, 0) : stream.views.front();
        return {view, offset};
    }

    int add_image(const std::vector<std::uint8_t>& png) {
        return append(blobs, png.data(), png.size()).first;
    }

    // An accessor of `count` values at `place` (view, offset), the last in the list.
    tinygltf::Accessor& new_accessor(std::pair<int, std::size_t> place, int component_type, std::size_t count,
                                     int type) {
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
        tinygltf::Accessor& accessor =
            new_accessor(append(stream, values.data(), values.size() * sizeof(Vector)),
                         TINYGLTF_COMPONENT_TYPE_FLOAT, values.size(), type);
        if (bounds && !values.empty()) {
            Vector lo = values[0], hi = values[0];
            for (const Vector& v : values) {
                lo = lo.cwiseMin(v);
                hi = hi.cwiseMax(v);
            }
            for (int c = 0; c < lo.size(); ++c) {
                accessor.minValues.push_back(json_number(lo[c]));
                accessor.maxValues.push_back(json_number(hi[c]));
            }
        }
        return int(gltf.accessors.size()) - 1;
    }

    int add_indices(const std::vector<std::uint32_t>& values, int index_bytes) {
        if (index_bytes == 4) {
            new_accessor(append(indices, values.data(), values.size() * 4),
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, values.size(), TINYGLTF_TYPE_SCALAR);
        } else {
            const std::vector<std::uint16_t> narrow(values.begin(), values.end());
            new_accessor(append(indices, narrow.data(), narrow.size() * 2, 2),
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, narrow.size(), TINYGLTF_TYPE_SCALAR);
        }
        return int(gltf.accessors.size()) - 1;
    }

    int level_mesh(int mesh) {
        if (mesh >= level_meshes_begin.back()) return mesh;
        auto [at, added] = level_copies.try_emplace(mesh, int(gltf.meshes.size()));
        if (added) gltf.meshes.push_back(tinygltf::Mesh(gltf.meshes[std::size_t(mesh)]));
        return at->second;
    }

    void start_level() {
        level_meshes_begin.push_back(int(gltf.meshes.size()));
        level_copies.clear();
    }

    // Lays the streams out in buffer 0, in a fixed order, and places the views;
    // the level buffers follow it.
    void finish() {
        gltf.buffers.resize(1 + level_buffers.size());
        for (std::size_t k = 0; k < level_buffers.size(); ++k) gltf.buffers[1 + k].data = level_buffers[k];
        std::vector<unsigned char>& data = gltf.buffers[0].data;
        for (Stream* stream : {&vec3, &vec2, &vec4, &indices, &blobs}) {
            if (stream->bytes.empty()) continue;
            while (data.size() % 4) data.push_back(0);
            std::size_t base = data.size();
            data.insert(data.end(), stream->bytes.begin(), stream->bytes.end());
            for (int view : stream->views) {
                gltf.bufferViews[view].byteOffset += base;
                if (stream->shared) gltf.bufferViews[view].byteLength = stream->bytes.size();
            }
        }
    }
};

// A primitive without texture coordinates is drawn in its material's colours
// alone (renderer/fragment_stage.cpp), and a glTF texture needs them (glTF
// 2.0, 3.9.2; the validator's MESH_PRIMITIVE_TOO_FEW_TEXCOORDS): its material
// is written without textures.
bool drawn_untextured(const Model& model, const Primitive& primitive) {
    return primitive.material >= 0 && primitive.uvs.empty() &&
           samples_textures(model.materials[std::size_t(primitive.material)]);
}

// Which way each material is drawn: with its textures (or by nothing: as it
// is), without them, or both.
struct MaterialUse {
    std::vector<bool> textured, untextured;
};

MaterialUse material_use(const Model& model) {
    MaterialUse use{std::vector<bool>(model.materials.size(), false),
                    std::vector<bool>(model.materials.size(), false)};
    for (const Node& node : model.nodes)
        for (const Primitive& primitive : node.primitives)
            if (primitive.material >= 0)
                (drawn_untextured(model, primitive) ? use.untextured
                                                    : use.textured)[std::size_t(primitive.material)] = true;
    for (std::size_t m = 0; m < model.materials.size(); ++m)
        use.textured[m] = use.textured[m] || !use.untextured[m];
    return use;
}

// The file a path leads to, as its device and inode (links resolved); none where there is none.
std::optional<std::pair<dev_t, ino_t>> file_identity(const fs::path& path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return std::nullopt;
    return std::pair{status.st_dev, status.st_ino};
}

// Whether the file `name` beside `target` is one the levels were read from
// (docs/design.md: Files): exporting beside the model would write over it.
bool was_read(const Writer& w, const fs::path& target, const std::string& name) {
    const auto identity = file_identity(target.parent_path() / name);
    return identity && w.read_files.count(*identity);
}

// A .gltf's buffer file beside it: NAME.bin, or NAME_2.bin, ... where NAME.bin was read.
std::string buffer_file_name(const Writer& w, const fs::path& target) {
    std::string name = target.stem().string() + ".bin";
    for (int again = 2; was_read(w, target, name); ++again)
        name = target.stem().string() + "_" + std::to_string(again) + ".bin";
    return name;
}

// A .gltf's image file beside it: named after its texture where that makes a
// plain .png name, else after the target. Never an image the levels were read
// from: exporting beside the model would re-encode it.
std::string image_file_name(Writer& w, const Texture& texture, const fs::path& target, int index) {
    const auto usable = [&](const std::string& name) {
        return !w.image_files.count(name) && !was_read(w, target, name);
    };
    std::string name = fs::path(texture.name).filename().string();
    if (fs::path(name).extension() != ".png" || name.find_first_of("/\\ ") != std::string::npos ||
        !usable(name)) {
        const std::string stem = target.stem().string() + "_texture_" + std::to_string(index);
        name = stem + ".png";
        for (int again = 2; !usable(name); ++again) name = stem + "_" + std::to_string(again) + ".png";
    }
    w.image_files.insert(name);
    return name;
}

// The textures a material drawn with them samples, as PNG images: in the
// .glb's buffer, or as files beside a .gltf (named after the texture where
// that makes a plain .png name).
void add_images(Writer& w, const Model& model, const MaterialUse& use, const fs::path& target, bool binary,
                int threads) {
    std::vector<bool> sampled(model.textures.size(), false);
    for (std::size_t m = 0; m < model.materials.size(); ++m)
        for (const auto& slot : texture_slots(model.materials[m]))
            if (use.textured[m] && slot.index >= 0) sampled[std::size_t(slot.index)] = true;
    // A texture equal to one already written (a chain's levels share the original's) is referred to, not
    // stored again.
    w.textures.assign(model.textures.size(), -1);
    std::vector<std::size_t> fresh;
    for (std::size_t i = 0; i < model.textures.size(); ++i) {
        if (!sampled[i]) continue;
        int next = int(w.gltf.textures.size() + fresh.size());
        // (Digests only for chains: a single model's textures are distinct, and hashing pages costs.)
        auto [at, added] = w.share ? w.texture_of.try_emplace(texture_digest(model.textures[i]), next)
                                   : std::pair{w.texture_of.end(), true};
        w.textures[i] = added ? next : at->second;
        if (added) fresh.push_back(i);
    }
    // PNG encoding dominates an LoD export: encode the textures in parallel, store them in order.
    std::vector<std::vector<std::uint8_t>> encoded(fresh.size());
    parallel_for(fresh.size(), threads, [&](std::size_t k) {
        const Texture& texture = model.textures[fresh[k]];
        encoded[k] = texture.image16.empty() ? encode_png(texture.image) : encode_png16(texture.image16);
    });
    for (std::size_t k = 0; k < fresh.size(); ++k) {
        const Texture& texture = model.textures[fresh[k]];
        const std::vector<std::uint8_t>& png = encoded[k];
        const int index = int(w.gltf.images.size());
        tinygltf::Image image;
        image.name = texture.name;
        image.mimeType = "image/png";
        if (binary) {
            image.bufferView = w.add_image(png);
        } else {
            const std::string name = image_file_name(w, texture, target, index);
            image.uri = file_uri(name);
            write_file_atomically((target.parent_path() / name).string(), png);
        }
        w.gltf.images.push_back(image);
        tinygltf::Texture gltf_texture;
        gltf_texture.source = index;
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

tinygltf::Material gltf_material(Writer& w, const Material& material) {
    tinygltf::Material out;
    out.name = material.name;
    out.pbrMetallicRoughness.baseColorFactor.clear();
    for (int c = 0; c < 4; ++c)
        out.pbrMetallicRoughness.baseColorFactor.push_back(json_number(material.base_color[c]));
    auto texture = [&](int index) { return index < 0 ? -1 : w.textures[std::size_t(index)]; };
    out.pbrMetallicRoughness.baseColorTexture.index = texture(material.base_color_texture);
    out.pbrMetallicRoughness.metallicFactor = 0;
    out.pbrMetallicRoughness.roughnessFactor = 1;
    out.normalTexture.index = texture(material.normal_texture);
    out.doubleSided = material.double_sided;
    out.alphaMode = enum_name(alpha_modes(), material.alpha_mode);
    if (material.alpha_mode == AlphaMode::mask) out.alphaCutoff = json_number(material.alpha_cutoff);
    out.extras = material_extras(material, texture(material.height_texture));
    auto add_extension = [&](const char* name, tinygltf::Value value) {
        out.extensions[name] = std::move(value);
        if (std::find(w.gltf.extensionsUsed.begin(), w.gltf.extensionsUsed.end(), name) ==
            w.gltf.extensionsUsed.end())
            w.gltf.extensionsUsed.push_back(name);
    };
    if (material.specular_glossiness)
        add_extension(specular_glossiness_name,
                      specular_glossiness_extension(material, texture(material.base_color_texture),
                                                    texture(material.specular_texture)));
    if (const auto& specular = material.specular_extension)
        add_extension(specular_extension_name, specular_extension_value(*specular, texture(specular->texture),
                                                                        texture(specular->color_texture)));
    return out;
}

// Its glTF index: an equal material's where the levels share them.
int add_material(Writer& w, const Material& material) {
    const tinygltf::Material out = gltf_material(w, material);
    const auto equal =
        w.share ? std::find(w.gltf.materials.begin(), w.gltf.materials.end(), out) : w.gltf.materials.end();
    if (equal != w.gltf.materials.end()) return int(equal - w.gltf.materials.begin());
    w.gltf.materials.push_back(out);
    return int(w.gltf.materials.size()) - 1;
}

// Each material as its primitives draw it (material_use); drawn both ways, the one without textures follows.
void add_materials(Writer& w, const Model& model, const MaterialUse& use) {
    w.materials.clear();
    w.untextured_materials.clear();
    for (std::size_t m = 0; m < model.materials.size(); ++m) {
        Material untextured = model.materials[m];
        for (const auto& slot : texture_slots(untextured)) *slot.index = -1;
        w.materials.push_back(add_material(w, use.textured[m] ? model.materials[m] : untextured));
        w.untextured_materials.push_back(use.textured[m] && use.untextured[m] ? add_material(w, untextured)
                                                                              : w.materials.back());
    }
}

int material_of(const Writer& w, const Model& model, const Primitive& primitive) {
    if (primitive.material < 0) return -1;
    return (drawn_untextured(model, primitive) ? w.untextured_materials
                                               : w.materials)[std::size_t(primitive.material)];
}

// FNV-1a over a node's positions and indices: finds candidates for sharing.
std::uint64_t geometry_hash(const Node& node) {
    std::uint64_t h = 14695981039346656037ull;
    auto mix = [&](const void* data, std::size_t bytes) {
        for (std::size_t i = 0; i < bytes; ++i)
            h = (h ^ static_cast<const std::uint8_t*>(data)[i]) * 1099511628211ull;
    };
    for (const Primitive& p : node.primitives) {
        mix(p.positions.data(), p.positions.size() * sizeof(p.positions[0]));
        mix(p.indices.data(), p.indices.size() * sizeof(p.indices[0]));
    }
    return h;
}

bool same_primitives(const Node& a, const Node& b) {
    if (a.primitives.size() != b.primitives.size()) return false;
    for (std::size_t i = 0; i < a.primitives.size(); ++i) {
        const Primitive &x = a.primitives[i], &y = b.primitives[i];
        if (x.positions != y.positions || x.normals != y.normals || x.uvs != y.uvs ||
            x.tangents != y.tangents || x.indices != y.indices || x.polygon_count != y.polygon_count)
            return false;
    }
    return true;
}

// A mesh already written with the same primitives and glTF materials, or -1.
int written_mesh(const Writer& w, const Node& node, std::uint64_t hash, const std::vector<int>& materials) {
    auto [begin, end] = w.meshes.equal_range(hash);
    for (auto it = begin; it != end; ++it)
        if (it->second.materials == materials && same_primitives(*it->second.node, node))
            return it->second.mesh;
    return -1;
}

// The nodes in the model's order (the root first), each with its mesh.
void add_nodes(Writer& w, const Model& model) {
    // tinygltf's types copy (not move) when a vector grows: reserve everything up front.
    std::size_t meshes = 0, primitives = 0;
    for (const Node& node : model.nodes) {
        meshes += node.has_geometry();
        primitives += node.primitives.size();
    }
    w.gltf.nodes.reserve(w.gltf.nodes.size() + model.nodes.size());
    w.gltf.meshes.reserve(w.gltf.meshes.size() + meshes);
    w.gltf.accessors.reserve(w.gltf.accessors.size() + primitives * 5);
    for (const Node& node : model.nodes) {
        tinygltf::Node out;
        out.name = node.name;
        for (int child : node.children) out.children.push_back(child + w.node_offset);
        out.extras_json_string = node_extras_json(node);
        // A node with no member at all (an unnamed, empty OBJ group) is named
        // by its index: glTF readers differ on empty objects, and tinygltf wrote null.
        if (out.name.empty() && out.children.empty() && !node.has_geometry() &&
            out.extras_json_string.empty())
            out.name = "node " + std::to_string(w.gltf.nodes.size());
        std::vector<int> materials;
        for (const Primitive& primitive : node.primitives)
            materials.push_back(material_of(w, model, primitive));
        const std::uint64_t hash = w.share && node.has_geometry() ? geometry_hash(node) : 0;
        const int shared = w.share && node.has_geometry() ? written_mesh(w, node, hash, materials) : -1;
        if (shared >= 0) {
            out.mesh = w.level_mesh(shared);
        } else if (node.has_geometry()) {
            tinygltf::Mesh mesh;
            mesh.name = node.name;
            for (const Primitive& primitive : node.primitives) {
                const VertexLayout layout = vertex_layout(primitive, model);
                tinygltf::Primitive p;
                p.mode = TINYGLTF_MODE_TRIANGLES;
                p.material = materials[mesh.primitives.size()];
                p.attributes["POSITION"] = w.add_accessor(primitive.positions, TINYGLTF_TYPE_VEC3, true);
                if (layout.normals)
                    p.attributes["NORMAL"] = w.add_accessor(primitive.normals, TINYGLTF_TYPE_VEC3, false);
                if (layout.uvs)
                    p.attributes["TEXCOORD_0"] = w.add_accessor(primitive.uvs, TINYGLTF_TYPE_VEC2, false);
                if (layout.tangents)
                    p.attributes["TANGENT"] = w.add_accessor(primitive.tangents, TINYGLTF_TYPE_VEC4, false);
                p.indices = w.add_indices(primitive.indices, layout.index_bytes);
                p.extras = primitive_extras(primitive);
                mesh.primitives.push_back(p);
            }
            w.gltf.meshes.push_back(std::move(mesh));
            out.mesh = int(w.gltf.meshes.size()) - 1;
            if (w.share) w.meshes.emplace(hash, Writer::WrittenMesh{&node, materials, out.mesh});
        }
        w.gltf.nodes.push_back(std::move(out));
    }
}

// Babylon.js loads MSFT_lod levels coarsest first, all at once, each level on
// completion disposing the one before; a level that finishes before a coarser
// one (all its parts already loading for another level) breaks the load. It
// holds a level's first request of a URI back until the coarser level is done,
// so each level but the coarsest keeps the indices of its smallest primitive
// in a buffer of its own, written as a data URI (bytes: one small index list
// a level, base64): Babylon then completes the levels in order, and a client
// that does not defer reads one more small buffer.
void sequence_levels(Writer& w) {
    const std::size_t levels = w.level_meshes_begin.size();
    auto meshes_of = [&](std::size_t k) {
        return std::pair{std::size_t(w.level_meshes_begin[k]),
                         k + 1 < levels ? std::size_t(w.level_meshes_begin[k + 1]) : w.gltf.meshes.size()};
    };
    std::map<int, std::set<std::size_t>> levels_of;  // an index accessor -> the levels drawing it
    for (std::size_t k = 0; k < levels; ++k)
        for (std::size_t m = meshes_of(k).first; m < meshes_of(k).second; ++m)
            for (const tinygltf::Primitive& p : w.gltf.meshes[m].primitives) levels_of[p.indices].insert(k);
    for (std::size_t k = 0; k + 1 < levels; ++k) {  // the coarsest, loaded first, waits for nothing
        tinygltf::Primitive* smallest = nullptr;
        for (std::size_t m = meshes_of(k).first; m < meshes_of(k).second; ++m)
            for (tinygltf::Primitive& p : w.gltf.meshes[m].primitives)
                if (!smallest || w.gltf.accessors[std::size_t(p.indices)].count <
                                     w.gltf.accessors[std::size_t(smallest->indices)].count)
                    smallest = &p;
        if (!smallest) continue;
        tinygltf::Accessor accessor = w.gltf.accessors[std::size_t(smallest->indices)];
        const std::size_t bytes =
            accessor.count *
            std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(accessor.componentType)));
        const auto begin = w.indices.bytes.begin() +
                           std::ptrdiff_t(accessor.byteOffset);  // the indices' view starts the stream
        w.level_buffers.emplace_back(begin, begin + std::ptrdiff_t(bytes));
        tinygltf::BufferView view;
        view.buffer = int(w.level_buffers.size());
        view.byteLength = bytes;
        view.target = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
        w.gltf.bufferViews.push_back(view);
        accessor.bufferView = int(w.gltf.bufferViews.size()) - 1;
        accessor.byteOffset = 0;
        std::set<std::size_t>& drawn_by = levels_of[smallest->indices];
        if (drawn_by.size() == 1) {  // the level's own accessor moves
            w.gltf.accessors[std::size_t(smallest->indices)] = accessor;
        } else {  // shared with other levels: this level draws a copy, they the original
            drawn_by.erase(k);
            w.gltf.accessors.push_back(accessor);
            smallest->indices = int(w.gltf.accessors.size()) - 1;
        }
    }
}

// The finest level's root is the scene; the others hang off its MSFT_lod
// extension, coarsest last, with switch hints in extras.MSFT_screencoverage
// (KhronosGroup/glTF, extensions/2.0/Vendor/MSFT_lod) and extras.boxlod.switch_distances.
// A model with an origin (a city file's) hangs under a node that moves it there
// and names the file's reference system.
void add_scene(Writer& w, const std::vector<int>& roots, const std::vector<LodSwitch>& switches,
               const Node& finest_root, const Eigen::Vector3d& origin, const std::string& reference_system) {
    tinygltf::Scene scene;
    scene.nodes = {roots[0]};
    if (!origin.isZero() || !reference_system.empty()) {
        tinygltf::Node placed;
        placed.name = "origin";
        placed.translation = {origin.x(), origin.y(), origin.z()};
        placed.children = {roots[0]};
        placed.extras = origin_node_extras(reference_system);
        w.gltf.nodes.push_back(std::move(placed));
        scene.nodes = {int(w.gltf.nodes.size()) - 1};
    }
    w.gltf.scenes.push_back(scene);
    w.gltf.defaultScene = 0;
    if (roots.size() < 2) return;
    tinygltf::Node& finest = w.gltf.nodes[std::size_t(roots[0])];
    tinygltf::Value::Array ids;
    for (std::size_t k = 1; k < roots.size(); ++k) ids.emplace_back(roots[k]);
    finest.extensions["MSFT_lod"] = tinygltf::Value(tinygltf::Value::Object{{"ids", tinygltf::Value(ids)}});
    finest.extras_json_string = node_extras_json(finest_root, switches);
    w.gltf.extensionsUsed.push_back("MSFT_lod");
}

}  // namespace

tinygltf::Model gltf_document(const std::vector<const Model*>& levels, const std::vector<LodSwitch>& switches,
                              const std::filesystem::path& target, bool binary, int threads) {
    Writer w;
    if (levels.empty() || switches.size() + 1 != levels.size())
        throw std::logic_error("export_gltf_lods: one switch per level after the first");
    // Nothing is written that boxlod would refuse to read (NaN, no triangles, ...).
    for (const Model* model : levels) validate_model(*model);
    w.gltf.asset.version = "2.0";
    w.gltf.asset.generator = "boxlod";
    w.gltf.asset.extras = asset_extras(*levels[0]);
    w.share = levels.size() > 1;
    for (const Model* model : levels)
        for (const std::string& file : model->read_files)
            if (const auto identity = file_identity(file)) w.read_files.insert(*identity);
    std::vector<int> roots;
    for (const Model* model : levels) {
        w.node_offset = int(w.gltf.nodes.size());
        roots.push_back(w.node_offset);
        w.start_level();
        const MaterialUse use = material_use(*model);
        add_images(w, *model, use, target, binary, threads);
        add_materials(w, *model, use);
        add_nodes(w, *model);
    }
    if (w.share) sequence_levels(w);
    add_scene(w, roots, switches, levels[0]->nodes[0], levels[0]->origin, levels[0]->reference_system);
    w.finish();
    if (!binary) w.gltf.buffers[0].uri = buffer_file_name(w, target);  // a file name; written as its URI
    return std::move(w.gltf);
}

}  // namespace boxlod
