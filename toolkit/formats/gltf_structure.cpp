#include "toolkit/formats/gltf_structure.h"

#include "base/input_error.h"
#include "toolkit/formats/gltf_extras.h"
#include "toolkit/formats/gltf_json.h"
#include "toolkit/formats/gltf_texture_transform.h"
#include "toolkit/formats/json_input.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>
#include <vector>

namespace boxlod {
namespace {

std::uint32_t little_endian_u32(std::string_view bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = v << 8 | std::uint8_t(bytes[at + std::size_t(i)]);
    return v;
}

struct Glb {
    std::string_view json;
    std::size_t binary_chunk = 0;  // bytes of the BIN chunk, 0 without one
};

// glTF 2.0, 4.4: a 12-byte header, then chunks of (length, type, data).
Glb split_glb(std::string_view bytes, const std::string& file) {
    if (bytes.size() < 20 || bytes.substr(0, 4) != "glTF")
        throw_input_error(file, "", "not a glb file (no 'glTF' header)");
    if (little_endian_u32(bytes, 4) != 2) throw_input_error(file, "header", "glb version is not 2");
    std::size_t length = little_endian_u32(bytes, 8);
    if (length > bytes.size())
        throw_input_error(file, "header",
                          "declares " + std::to_string(length) + " bytes, the file has " +
                              std::to_string(bytes.size()) + " (truncated file?)");
    Glb glb;
    std::size_t at = 12;
    for (int chunk = 0; at + 8 <= length; ++chunk) {
        std::size_t chunk_length = little_endian_u32(bytes, at);
        std::uint32_t type = little_endian_u32(bytes, at + 4);
        if (!range_fits(at + 8, chunk_length, length))
            throw_input_error(file, "chunk " + std::to_string(chunk),
                              "runs past the end of the file (truncated file?)");
        std::string_view data = bytes.substr(at + 8, chunk_length);
        if (chunk == 0 && type != 0x4E4F534Au)
            throw_input_error(file, "chunk 0", "the first chunk is not JSON");
        if (chunk == 0) glb.json = data;
        if (chunk == 1 && type == 0x004E4942u) glb.binary_chunk = chunk_length;
        at += 8 + chunk_length;
    }
    if (glb.json.empty()) throw_input_error(file, "", "no JSON chunk");
    return glb;
}

// A non-negative integer member, `fallback` when absent.
std::size_t size_member(const nlohmann::json& object, const char* key, std::size_t fallback,
                        const std::string& file, const std::string& place) {
    auto found = object.find(key);
    if (found == object.end()) return fallback;
    if (!found->is_number_unsigned())
        throw_input_error(file, place, std::string(key) + " must be a non-negative integer");
    return found->get<std::size_t>();
}

const nlohmann::json& array_member(const nlohmann::json& root, const char* key, const std::string& file) {
    static const nlohmann::json none = nlohmann::json::array();
    auto found = root.find(key);
    if (found == root.end()) return none;
    if (!found->is_array()) throw_input_error(file, key, "must be an array");
    return *found;
}

// The JSON kind of a member as the glTF 2.0 schema gives it (spec section 5,
// Properties Reference). tinygltf skips a member of another kind without a
// word, and the file would be read as if the member were absent.
enum class Kind {
    object,
    array,
    string,
    boolean,
    number,
    index,
    count,
    numbers,
    indices,
    strings,
    index_values,
    ints
};

struct MemberKind {
    const char* path;  // from the root: "materials[].alphaCutoff"; [] walks an array's elements
    Kind kind;
    std::size_t length = 0;  // numbers: exactly this many (0: any)
};

// The members boxlod or tinygltf read.
constexpr MemberKind member_kinds[] = {
    {"asset", Kind::object},
    {"asset.version", Kind::string},
    {"scene", Kind::index},
    {"extensionsUsed", Kind::strings},
    {"extensionsRequired", Kind::strings},
    {"bufferViews[].byteStride", Kind::index},  // the others: check_gltf_structure, with their ranges
    {"nodes[].skin", Kind::index},
    {"scenes[].nodes", Kind::indices},
    {"nodes[].children", Kind::indices},
    {"nodes[].mesh", Kind::index},
    {"nodes[].camera", Kind::index},
    {"nodes[].extensions.MSFT_lod.ids", Kind::indices},
    {"nodes[].matrix", Kind::numbers, 16},
    {"nodes[].translation", Kind::numbers, 3},
    {"nodes[].rotation", Kind::numbers, 4},
    {"nodes[].scale", Kind::numbers, 3},
    {"meshes[].primitives", Kind::array},
    {"meshes[].primitives[].attributes", Kind::index_values},
    {"meshes[].primitives[].indices", Kind::index},
    {"meshes[].primitives[].material", Kind::index},
    {"meshes[].primitives[].mode", Kind::index},
    {"meshes[].primitives[].extras.boxlod.polygons", Kind::index},  // boxlod's extras (gltf_extras.h)
    // What boxlod reads through tinygltf's Value, which keeps every integer in an int.
    {"meshes[].primitives[].extras.boxlod", Kind::ints},
    {"nodes[].extras.boxlod", Kind::ints},
    {"nodes[].extensions.MSFT_lod", Kind::ints},
    {"materials[].extras.boxlod", Kind::ints},
    {"materials[].extensions.KHR_materials_pbrSpecularGlossiness", Kind::ints},
    {"materials[].extensions.KHR_materials_specular", Kind::ints},
    {"accessors[].bufferView", Kind::index},
    {"accessors[].byteOffset", Kind::count},
    {"accessors[].componentType", Kind::index},
    {"accessors[].count", Kind::count},  // tinygltf keeps counts and offsets whole
    {"accessors[].type", Kind::string},
    {"accessors[].normalized", Kind::boolean},
    {"accessors[].min", Kind::numbers},
    {"accessors[].max", Kind::numbers},
    {"accessors[].sparse", Kind::object},
    {"materials[].alphaMode", Kind::string},
    {"materials[].alphaCutoff", Kind::number},
    {"materials[].doubleSided", Kind::boolean},
    {"materials[].extras.boxlod.height_texture", Kind::index},
    {"materials[].emissiveFactor", Kind::numbers, 3},
    {"materials[].pbrMetallicRoughness", Kind::object},
    {"materials[].pbrMetallicRoughness.baseColorFactor", Kind::numbers, 4},
    {"materials[].pbrMetallicRoughness.metallicFactor", Kind::number},
    {"materials[].pbrMetallicRoughness.roughnessFactor", Kind::number},
    {"materials[].pbrMetallicRoughness.baseColorTexture", Kind::object},
    {"materials[].pbrMetallicRoughness.baseColorTexture.index", Kind::index},
    {"materials[].pbrMetallicRoughness.baseColorTexture.texCoord", Kind::index},
    {"materials[].pbrMetallicRoughness.metallicRoughnessTexture", Kind::object},
    {"materials[].normalTexture", Kind::object},
    {"materials[].normalTexture.index", Kind::index},
    {"materials[].normalTexture.texCoord", Kind::index},
    {"materials[].normalTexture.scale", Kind::number},
    {"materials[].occlusionTexture", Kind::object},
    {"materials[].emissiveTexture", Kind::object},
    {"materials[].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.offset",
     Kind::numbers, 2},
    {"materials[].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.rotation",
     Kind::number},
    {"materials[].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.scale",
     Kind::numbers, 2},
    {"materials[].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.texCoord",
     Kind::index},
    {"materials[].normalTexture.extensions.KHR_texture_transform.offset", Kind::numbers, 2},
    {"materials[].normalTexture.extensions.KHR_texture_transform.rotation", Kind::number},
    {"materials[].normalTexture.extensions.KHR_texture_transform.scale", Kind::numbers, 2},
    {"materials[].normalTexture.extensions.KHR_texture_transform.texCoord", Kind::index},
    {"materials[].extensions.KHR_materials_specular", Kind::object},  // the material extensions boxlod reads
    {"materials[].extensions.KHR_materials_pbrSpecularGlossiness", Kind::object},
    {"textures[].source", Kind::index},
    {"textures[].sampler", Kind::index},
    {"samplers[].magFilter", Kind::index},
    {"samplers[].minFilter", Kind::index},
    {"samplers[].wrapS", Kind::index},
    {"samplers[].wrapT", Kind::index},
    {"images[].uri", Kind::string},
    {"images[].mimeType", Kind::string},
    {"buffers[].uri", Kind::string},
    {"cameras[].type", Kind::string},
    {"cameras[].perspective", Kind::object},
    {"cameras[].orthographic", Kind::object},
};

const char* kind_text(Kind kind) {
    switch (kind) {
    case Kind::object: return "an object";
    case Kind::array: return "an array";
    case Kind::string: return "a string";
    case Kind::boolean: return "true or false";
    case Kind::number: return "a number";
    case Kind::index: return "a non-negative integer below 2^31";
    case Kind::count: return "a non-negative integer";
    case Kind::index_values: return "an object of non-negative integers below 2^31";
    case Kind::ints: return "free of integers beyond 32 bits";
    case Kind::numbers: return "an array of numbers";
    case Kind::indices: return "an array of non-negative integers below 2^31";
    case Kind::strings: return "an array of strings";
    }
    return "";
}

// tinygltf 2.7 keeps every index in an int, truncating larger ones to another index.
bool is_index(const nlohmann::json& value) {
    return value.is_number_unsigned() && value.get<std::uint64_t>() <= std::uint64_t(INT_MAX);
}

// Every integer within `value` fits an int (a walk with a stack: the JSON is at most max_nesting_depth deep).
bool integers_fit_int(const nlohmann::json& value) {
    std::vector<const nlohmann::json*> pending{&value};
    while (!pending.empty()) {
        const nlohmann::json& v = *pending.back();
        pending.pop_back();
        if (v.is_number_unsigned() && v.get<std::uint64_t>() > std::uint64_t(INT_MAX)) return false;
        if (v.is_number_integer() && !v.is_number_unsigned() && v.get<std::int64_t>() < INT_MIN) return false;
        if (v.is_structured())
            for (const nlohmann::json& member : v) pending.push_back(&member);
    }
    return true;
}

bool has_kind(const nlohmann::json& value, Kind kind, std::size_t length) {
    auto all = [&](auto test) { return value.is_array() && std::all_of(value.begin(), value.end(), test); };
    switch (kind) {
    case Kind::object: return value.is_object();
    case Kind::array: return value.is_array();
    case Kind::string: return value.is_string();
    case Kind::boolean: return value.is_boolean();
    case Kind::number: return value.is_number();
    case Kind::index: return is_index(value);
    case Kind::count: return value.is_number_unsigned();
    case Kind::index_values: return value.is_object() && std::all_of(value.begin(), value.end(), is_index);
    case Kind::ints: return integers_fit_int(value);
    case Kind::numbers:
        return all([](const nlohmann::json& v) { return v.is_number(); }) &&
               (length == 0 || value.size() == length);
    case Kind::indices: return all(is_index);
    case Kind::strings: return all([](const nlohmann::json& v) { return v.is_string(); });
    }
    return false;
}

// Checks `path` (its segments from `segment` on) below `value`, named `place` so far.
void check_member(const nlohmann::json& value, const MemberKind& member, std::string_view path,
                  const std::string& place, const std::string& file) {
    const std::size_t dot = path.find('.');
    std::string_view segment = path.substr(0, dot);
    const bool each = segment.ends_with("[]");
    if (each) segment.remove_suffix(2);
    if (!value.is_object()) return;  // a parent of the wrong kind is its own row's finding
    const auto found = value.find(std::string(segment));
    if (found == value.end()) return;
    const std::string here = place.empty() ? std::string(segment) : place + "." + std::string(segment);
    if (dot == std::string_view::npos) {
        if (!has_kind(*found, member.kind, member.length))
            throw_input_error(file, here,
                              std::string("must be ") + kind_text(member.kind) +
                                  (member.length ? " of length " + std::to_string(member.length) : ""));
        return;
    }
    if (!each) return check_member(*found, member, path.substr(dot + 1), here, file);
    if (!found->is_array()) throw_input_error(file, here, "must be an array");
    for (std::size_t i = 0; i < found->size(); ++i)
        check_member((*found)[i], member, path.substr(dot + 1), here + "[" + std::to_string(i) + "]", file);
}

// What a glTF 2.0 reader must refuse (spec, 3.2 Asset and 3.12 Extensions),
// before tinygltf reads the file: a glTF 1.0 file fails there on the first
// member 1.0 spells otherwise, and a Draco-compressed one on its accessors,
// with messages that name neither.
void check_version_and_required_extensions(const nlohmann::json& root, const std::string& file) {
    if (const auto asset = root.find("asset"); asset != root.end() && asset->is_object())
        if (const auto version = asset->find(
                "version");  // 1.0's is a string or a number; another kind is the schema's finding
            version != asset->end() &&
            (version->is_number() ||
             (version->is_string() && !version->get<std::string>().starts_with("2."))))
            throw_input_error(
                file, "asset.version",
                (version->is_string() ? "'" + version->get<std::string>() + "'" : version->dump()) +
                    " is not glTF 2 (boxlod reads glTF 2.0)");
    if (const auto required = root.find("extensionsRequired"); required != root.end() && required->is_array())
        for (const nlohmann::json& name : *required)
            if (name.is_string() && name != "MSFT_lod" && name != specular_glossiness_name &&
                name != specular_extension_name && name != texture_transform_name)
                throw_input_error(
                    file, "extensionsRequired",
                    "'" + name.get<std::string>() + "' is required, and boxlod does not read it");
}

// A buffer's or image's uri names a file relative to the glTF file, or is a
// data URI (glTF 2.0, 2.8: URIs): an absolute path or a file: URI would read
// whatever the path names (it said "File not found" of a file that exists).
void check_relative_uri(const nlohmann::json& item, const std::string& file, const std::string& place) {
    const auto uri = item.find("uri");
    if (uri == item.end() || !uri->is_string()) return;
    const std::string& text = uri->get_ref<const std::string&>();
    if (!text.starts_with("data:") &&
        file_name_of_uri(text).find('\0') != std::string::npos)  // read up to it
        throw_input_error(file, place, "uri '" + text + "' names a file with a NUL character");
    if (text.starts_with("/") || text.starts_with("file:"))
        throw_input_error(file, place,
                          "uri '" + text +
                              "' is absolute: glTF's URIs are relative to the file or data: URIs (glTF 2.0, "
                              "2.8), so a model names nothing by where it was made");
}

// Every `extensions` member, wherever it is, is an object (glTF 2.0, 3.12:
// extensions are a dictionary); a JSON nested at most max_nesting_depth deep
// keeps this recursion shallow.
void check_extensions(const nlohmann::json& value, const std::string& place, const std::string& file) {
    if (value.is_object()) {
        for (const auto& [key, member] : value.items()) {
            const std::string here = place.empty() ? key : place + "." + key;
            if (key == "extensions" && !member.is_object())
                throw_input_error(file, here, "must be an object");
            if (key != "extras") check_extensions(member, here, file);
        }
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i)
            check_extensions(value[i], place + "[" + std::to_string(i) + "]", file);
    }
}

}  // namespace

void check_gltf_structure(std::string_view bytes, bool binary, const std::string& file) {
    Glb glb = binary ? split_glb(bytes, file) : Glb{bytes, 0};
    // tinygltf's model holds each extras' or extensions' value as a Value of some 150 bytes and each node
    // in some hundreds, beside its parsed tree: measured up to 6 trees' worth (2 million empty nodes).
    check_json_input(glb.json, file, 7, "its JSON, read by tinygltf,");
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(glb.json);
    } catch (const nlohmann::json::exception& error) {
        throw_input_error(file, "", std::string("malformed JSON: ") + error.what());
    }
    if (!root.is_object()) throw_input_error(file, "", "the JSON is not an object");
    check_version_and_required_extensions(root, file);
    for (const MemberKind& member : member_kinds) check_member(root, member, member.path, "", file);
    check_extensions(root, "", file);

    const nlohmann::json& buffers = array_member(root, "buffers", file);
    std::vector<std::size_t> buffer_bytes;
    for (std::size_t b = 0; b < buffers.size(); ++b) {
        std::string place = "buffer " + std::to_string(b);
        if (!buffers[b].is_object()) throw_input_error(file, place, "must be an object");
        std::size_t length = size_member(buffers[b], "byteLength", 0, file, place);
        if (binary && b == 0 && !buffers[b].contains("uri") && length > glb.binary_chunk)
            throw_input_error(file, place,
                              "byteLength " + std::to_string(length) + " exceeds the " +
                                  std::to_string(glb.binary_chunk) + "-byte BIN chunk (truncated file?)");
        buffer_bytes.push_back(length);
        check_relative_uri(buffers[b], file, place);
    }
    const nlohmann::json& views = array_member(root, "bufferViews", file);
    for (std::size_t v = 0; v < views.size(); ++v) {
        std::string place = "bufferView " + std::to_string(v);
        if (!views[v].is_object()) throw_input_error(file, place, "must be an object");
        std::size_t buffer = size_member(views[v], "buffer", buffer_bytes.size(), file, place);
        if (buffer >= buffer_bytes.size()) throw_input_error(file, place, "buffer index out of range");
        std::size_t offset = size_member(views[v], "byteOffset", 0, file, place);
        std::size_t length = size_member(views[v], "byteLength", 0, file, place);
        if (!range_fits(offset, length, buffer_bytes[buffer]))
            throw_input_error(file, place,
                              "byteOffset " + std::to_string(offset) + " + byteLength " +
                                  std::to_string(length) + " runs past buffer " + std::to_string(buffer) +
                                  "'s " + std::to_string(buffer_bytes[buffer]) + " bytes");
    }
    const nlohmann::json& images = array_member(root, "images", file);
    for (std::size_t i = 0; i < images.size(); ++i) {
        std::string place = "image " + std::to_string(i);
        if (!images[i].is_object()) throw_input_error(file, place, "must be an object");
        if (images[i].contains("bufferView") &&
            size_member(images[i], "bufferView", 0, file, place) >= views.size())
            throw_input_error(file, place, "bufferView index out of range");
        check_relative_uri(images[i], file, place);
    }
}

}  // namespace boxlod
