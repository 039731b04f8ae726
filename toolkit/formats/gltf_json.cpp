// A glTF document's text without a JSON tree (toolkit/formats/gltf_json.h).
// Each member is written as tinygltf 2.7's Serialize* functions write it
// (which members are left out at their defaults), in the order nlohmann's
// std::map objects print keys; JsonText checks that order as it goes.
// A node's extras may come as text (tinygltf::Node::extras_json_string,
// "the extras as JSON"): a city's nodes are most of a file, and a tree of
// tinygltf::Value per node cost more than the writing.
#include "toolkit/formats/gltf_json.h"

#include "toolkit/formats/json_text.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace boxlod {
namespace {

bool double_equal(double a, double b) { return std::fabs(a - b) < 1e-12; }  // TINYGLTF_DOUBLE_EQUAL

bool equal_numbers(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!double_equal(a[i], b[i])) return false;
    return true;
}

// tinygltf's ValueToJson: a null (or binary) value is left out; an array or
// object with nothing else in it is written as null.
bool written(const tinygltf::Value& value) {
    return value.Type() != tinygltf::NULL_TYPE && value.Type() != tinygltf::BINARY_TYPE;
}

bool has_written_member(const tinygltf::Value& value) {
    if (value.IsArray()) {
        for (const tinygltf::Value& element : value.Get<tinygltf::Value::Array>())
            if (written(element)) return true;
        return false;
    }
    for (const auto& [name, member] : value.Get<tinygltf::Value::Object>())
        if (written(member)) return true;
    return false;
}

void write_value(JsonText& j, const tinygltf::Value& value) {
    switch (value.Type()) {
    case tinygltf::REAL_TYPE: return j.number(value.Get<double>());
    case tinygltf::INT_TYPE: return j.integer(value.Get<int>());
    case tinygltf::BOOL_TYPE: return j.boolean(value.Get<bool>());
    case tinygltf::STRING_TYPE: return j.string(value.Get<std::string>());
    default: break;
    }
    if (!has_written_member(value)) return j.null();
    if (value.IsArray()) {
        j.begin_array();
        for (const tinygltf::Value& element : value.Get<tinygltf::Value::Array>())
            if (written(element)) write_value(j, element);
        return j.end_array();
    }
    j.begin_object();
    for (const auto& [name, member] : value.Get<tinygltf::Value::Object>()) {
        if (!written(member)) continue;
        j.key(name);
        write_value(j, member);
    }
    j.end_object();
}

void extras(JsonText& j, const tinygltf::Value& value) {
    if (!written(value)) return;
    j.key("extras");
    write_value(j, value);
}

// An extension whose value writes as null is written as {} (tinygltf #97).
void extensions(JsonText& j, const tinygltf::ExtensionMap& map) {
    if (map.empty()) return;
    j.key("extensions");
    j.begin_object();
    for (const auto& [name, value] : map) {
        j.key(name);
        if (written(value) && (!(value.IsArray() || value.IsObject()) || has_written_member(value))) {
            write_value(j, value);
        } else {
            j.begin_object();
            j.end_object();
        }
    }
    j.end_object();
}

template <typename Number>
void numbers(JsonText& j, std::string_view name, const std::vector<Number>& values) {
    if (values.empty()) return;
    j.key(name);
    j.begin_array();
    for (Number v : values) {
        if constexpr (std::is_floating_point_v<Number>) {
            j.number(v);
        } else {
            j.integer(v);
        }
    }
    j.end_array();
}

void integer_member(JsonText& j, std::string_view name, std::int64_t value) {
    j.key(name);
    j.integer(value);
}

void number_member(JsonText& j, std::string_view name, double value) {
    j.key(name);
    j.number(value);
}

void boolean_member(JsonText& j, std::string_view name, bool value) {
    j.key(name);
    j.boolean(value);
}

void string_member(JsonText& j, std::string_view name, const std::string& value) {
    j.key(name);
    j.string(value);
}

void name_member(JsonText& j, const std::string& name) {
    if (!name.empty()) string_member(j, "name", name);
}

template <typename Item, typename Write>
void array_member(JsonText& j, std::string_view name, const std::vector<Item>& items, Write write) {
    if (items.empty()) return;
    j.key(name);
    j.begin_array();
    for (const Item& item : items) {
        j.begin_object();
        write(item);
        j.end_object();
    }
    j.end_array();
}

void accessor(JsonText& j, const tinygltf::Accessor& a) {
    if (a.sparse.isSparse) throw std::logic_error("glTF text: sparse accessors are not written");
    if (a.bufferView >= 0) integer_member(j, "bufferView", a.bufferView);
    if (a.byteOffset != 0) integer_member(j, "byteOffset", std::int64_t(a.byteOffset));
    integer_member(j, "componentType", a.componentType);
    integer_member(j, "count", std::int64_t(a.count));
    extras(j, a.extras);
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
        a.componentType == TINYGLTF_COMPONENT_TYPE_DOUBLE) {
        numbers(j, "max", a.maxValues);
        numbers(j, "min", a.minValues);
    } else {  // whole numbers (tinygltf #301)
        numbers(j, "max", std::vector<int>(a.maxValues.begin(), a.maxValues.end()));
        numbers(j, "min", std::vector<int>(a.minValues.begin(), a.minValues.end()));
    }
    name_member(j, a.name);
    if (a.normalized) boolean_member(j, "normalized", true);
    static const char* const types[] = {"", "", "VEC2", "VEC3", "VEC4"};
    const std::string type = a.type == TINYGLTF_TYPE_SCALAR ? "SCALAR"
                             : a.type >= 2 && a.type <= 4   ? types[a.type]
                                                            : "";
    if (type.empty())
        throw std::logic_error("glTF text: accessor type " + std::to_string(a.type) + " is not written");
    string_member(j, "type", type);
}

void asset(JsonText& j, const tinygltf::Asset& a) {
    if (!a.copyright.empty()) string_member(j, "copyright", a.copyright);
    extensions(j, a.extensions);
    if (!a.extras.Keys().empty()) extras(j, a.extras);
    if (!a.generator.empty()) string_member(j, "generator", a.generator);
    string_member(j, "version", a.version.empty() ? "2.0" : a.version);
}

void buffer_view(JsonText& j, const tinygltf::BufferView& v) {
    integer_member(j, "buffer", v.buffer);
    integer_member(j, "byteLength", std::int64_t(v.byteLength));
    if (v.byteOffset > 0) integer_member(j, "byteOffset", std::int64_t(v.byteOffset));
    if (v.byteStride >= 4) integer_member(j, "byteStride", std::int64_t(v.byteStride));
    extras(j, v.extras);
    name_member(j, v.name);
    if (v.target == TINYGLTF_TARGET_ARRAY_BUFFER || v.target == TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER)
        integer_member(j, "target", v.target);
}

// RFC 4648, 4 (what tinygltf writes; its encoder is not in its header).
std::string base64(const std::vector<unsigned char>& bytes) {
    static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t triple = std::uint32_t(bytes[i]) << 16;
        if (n > 1) triple |= std::uint32_t(bytes[i + 1]) << 8;
        if (n > 2) triple |= bytes[i + 2];
        for (std::size_t c = 0; c < 4; ++c) out += c <= n ? alphabet[(triple >> (18 - 6 * c)) & 63] : '=';
    }
    return out;
}

// A buffer's uri: `uri` as given, none (a .glb's BIN chunk), or its bytes as a data URI.
void buffer(JsonText& j, const tinygltf::Buffer& b, const std::string* uri) {
    integer_member(j, "byteLength", std::int64_t(b.data.size()));
    extras(j, b.extras);
    name_member(j, b.name);
    if (!uri) return;
    if (!uri->empty()) return string_member(j, "uri", *uri);
    string_member(j, "uri", "data:application/octet-stream;base64," + base64(b.data));
}

void image(JsonText& j, const tinygltf::Image& i) {
    if (i.uri.empty()) integer_member(j, "bufferView", i.bufferView);
    extensions(j, i.extensions);
    extras(j, i.extras);
    if (i.uri.empty()) string_member(j, "mimeType", i.mimeType);
    name_member(j, i.name);
    if (!i.uri.empty()) string_member(j, "uri", i.uri);
}

template <typename Info>
void texture_info(JsonText& j, std::string_view name, const Info& info, double scale = 1) {
    if (info.index < 0) return;
    j.key(name);
    j.begin_object();
    extensions(j, info.extensions);
    extras(j, info.extras);
    integer_member(j, "index", info.index);
    if (!double_equal(scale, 1)) number_member(j, "scale", scale);
    if (info.texCoord != 0) integer_member(j, "texCoord", info.texCoord);
    j.end_object();
}

void pbr(JsonText& j, const tinygltf::PbrMetallicRoughness& p) {
    const bool color = !equal_numbers(p.baseColorFactor, {1, 1, 1, 1}),
               metallic = !double_equal(p.metallicFactor, 1), roughness = !double_equal(p.roughnessFactor, 1);
    if (!color && !metallic && !roughness && p.baseColorTexture.index < 0 &&
        p.metallicRoughnessTexture.index < 0 && p.extensions.empty() && !written(p.extras))
        return;  // all defaults: left out (tinygltf #204)
    j.key("pbrMetallicRoughness");
    j.begin_object();
    if (color) numbers(j, "baseColorFactor", p.baseColorFactor);
    texture_info(j, "baseColorTexture", p.baseColorTexture);
    extensions(j, p.extensions);
    extras(j, p.extras);
    if (metallic) number_member(j, "metallicFactor", p.metallicFactor);
    texture_info(j, "metallicRoughnessTexture", p.metallicRoughnessTexture);
    if (roughness) number_member(j, "roughnessFactor", p.roughnessFactor);
    j.end_object();
}

void material(JsonText& j, const tinygltf::Material& m) {
    if (m.occlusionTexture.index >= 0)
        throw std::logic_error("glTF text: occlusion textures are not written");
    if (!double_equal(m.alphaCutoff, 0.5)) number_member(j, "alphaCutoff", m.alphaCutoff);
    if (m.alphaMode != "OPAQUE") string_member(j, "alphaMode", m.alphaMode);
    if (m.doubleSided) boolean_member(j, "doubleSided", true);
    if (!equal_numbers(m.emissiveFactor, {0, 0, 0})) numbers(j, "emissiveFactor", m.emissiveFactor);
    texture_info(j, "emissiveTexture", m.emissiveTexture);
    extensions(j, m.extensions);
    extras(j, m.extras);
    name_member(j, m.name);
    texture_info(j, "normalTexture", m.normalTexture, m.normalTexture.scale);
    pbr(j, m.pbrMetallicRoughness);
}

void primitive(JsonText& j, const tinygltf::Primitive& p) {
    if (!p.targets.empty()) throw std::logic_error("glTF text: morph targets are not written");
    j.key("attributes");
    j.begin_object();
    for (const auto& [name, index] : p.attributes) integer_member(j, name, index);
    j.end_object();
    extensions(j, p.extensions);
    extras(j, p.extras);
    if (p.indices > -1) integer_member(j, "indices", p.indices);
    if (p.material > -1) integer_member(j, "material", p.material);
    integer_member(j, "mode", p.mode);
}

void mesh(JsonText& j, const tinygltf::Mesh& m) {
    extensions(j, m.extensions);
    extras(j, m.extras);
    name_member(j, m.name);
    array_member(j, "primitives", m.primitives, [&](const tinygltf::Primitive& p) { primitive(j, p); });
    numbers(j, "weights", m.weights);
}

void node(JsonText& j, const tinygltf::Node& n) {
    if (n.skin != -1 || n.camera != -1 || !n.weights.empty())
        throw std::logic_error("glTF text: skins, cameras and weights are not written");
    numbers(j, "children", n.children);
    extensions(j, n.extensions);
    if (!n.extras_json_string.empty()) {
        j.key("extras");
        j.raw(n.extras_json_string);
    } else {
        extras(j, n.extras);
    }
    numbers(j, "matrix", n.matrix);
    if (n.mesh != -1) integer_member(j, "mesh", n.mesh);
    name_member(j, n.name);
    numbers(j, "rotation", n.rotation);
    numbers(j, "scale", n.scale);
    numbers(j, "translation", n.translation);
}

void sampler(JsonText& j, const tinygltf::Sampler& s) {
    extras(j, s.extras);
    if (s.magFilter != -1) integer_member(j, "magFilter", s.magFilter);
    if (s.minFilter != -1) integer_member(j, "minFilter", s.minFilter);
    integer_member(j, "wrapS", s.wrapS);
    integer_member(j, "wrapT", s.wrapT);
}

void scene(JsonText& j, const tinygltf::Scene& s) {
    extensions(j, s.extensions);
    extras(j, s.extras);
    name_member(j, s.name);
    numbers(j, "nodes", s.nodes);
}

void texture(JsonText& j, const tinygltf::Texture& t) {
    extensions(j, t.extensions);
    extras(j, t.extras);
    name_member(j, t.name);
    if (t.sampler > -1) integer_member(j, "sampler", t.sampler);
    if (t.source > -1) integer_member(j, "source", t.source);
}

// The document; buffer 0's uri is `bin_uri` (nullptr: none, a .glb's BIN chunk).
std::string document_text(const tinygltf::Model& d, const std::string* bin_uri) {
    if (!d.animations.empty() || !d.skins.empty() || !d.cameras.empty() || !d.lights.empty() ||
        !d.extensionsRequired.empty())
        throw std::logic_error(
            "glTF text: animations, skins, cameras, lights and required extensions are not written");
    JsonText j;
    // About what the text takes (manual: 400 bytes a node with its scope), so it grows once or twice.
    j.text.reserve(4096 + 400 * d.nodes.size() + 150 * d.accessors.size() +
                   100 * (d.meshes.size() + d.materials.size()));
    j.begin_object();
    array_member(j, "accessors", d.accessors, [&](const tinygltf::Accessor& a) { accessor(j, a); });
    j.key("asset");
    j.begin_object();
    asset(j, d.asset);
    j.end_object();
    array_member(j, "bufferViews", d.bufferViews, [&](const tinygltf::BufferView& v) { buffer_view(j, v); });
    const std::string data_uri;
    array_member(j, "buffers", d.buffers, [&, k = std::size_t(0)](const tinygltf::Buffer& b) mutable {
        buffer(j, b, k++ == 0 ? bin_uri : b.uri.empty() ? &data_uri : &b.uri);
    });
    extensions(j, d.extensions);
    if (!d.extensionsUsed.empty()) {
        j.key("extensionsUsed");
        j.begin_array();
        for (const std::string& name : d.extensionsUsed) j.string(name);
        j.end_array();
    }
    extras(j, d.extras);
    array_member(j, "images", d.images, [&](const tinygltf::Image& i) { image(j, i); });
    array_member(j, "materials", d.materials, [&](const tinygltf::Material& m) { material(j, m); });
    array_member(j, "meshes", d.meshes, [&](const tinygltf::Mesh& m) { mesh(j, m); });
    array_member(j, "nodes", d.nodes, [&](const tinygltf::Node& n) { node(j, n); });
    array_member(j, "samplers", d.samplers, [&](const tinygltf::Sampler& s) { sampler(j, s); });
    if (d.defaultScene > -1) integer_member(j, "scene", d.defaultScene);
    array_member(j, "scenes", d.scenes, [&](const tinygltf::Scene& s) { scene(j, s); });
    array_member(j, "textures", d.textures, [&](const tinygltf::Texture& t) { texture(j, t); });
    j.end_object();
    return std::move(j.text);
}

void append_u32(std::string& out, std::uint32_t value) {
    for (int b = 0; b < 4; ++b) out += char((value >> (8 * b)) & 0xff);  // little-endian (glTF 2.0, 4.4.2)
}

}  // namespace

std::string gltf_text(const tinygltf::Model& document, const std::string& bin_uri) {
    return document_text(document, &bin_uri) + "\n";
}

std::string glb_bytes(const tinygltf::Model& document) {
    const std::string json = document_text(document, nullptr);
    const std::vector<unsigned char> empty;
    const std::vector<unsigned char>& bin = document.buffers.empty() ? empty : document.buffers[0].data;
    const std::size_t json_padded = (json.size() + 3) / 4 * 4, bin_padded = (bin.size() + 3) / 4 * 4;
    const std::size_t length = 12 + 8 + json_padded + (bin.empty() ? 0 : 8 + bin_padded);
    if (length > 0xffffffffu)
        throw std::logic_error("glb: " + std::to_string(length) + " bytes, more than a .glb holds");
    std::string out;
    out.reserve(length);
    out += "glTF";
    append_u32(out, 2);
    append_u32(out, std::uint32_t(length));
    append_u32(out, std::uint32_t(json_padded));
    append_u32(out, 0x4E4F534Au);  // "JSON"
    out += json;
    out.append(json_padded - json.size(), ' ');
    if (!bin.empty()) {
        append_u32(out, std::uint32_t(bin_padded));
        append_u32(out, 0x004E4942u);  // "BIN"
        out.append(reinterpret_cast<const char*>(bin.data()), bin.size());
        out.append(bin_padded - bin.size(), '\0');
    }
    return out;
}

std::string file_uri(const std::string& file_name) {
    static constexpr char hex[] = "0123456789ABCDEF";
    std::string uri;
    for (const char c : file_name) {
        const auto byte = static_cast<unsigned char>(c);
        if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
            c == '.' || c == '_' || c == '~') {
            uri += c;
        } else {
            uri += '%';
            uri += hex[byte >> 4];
            uri += hex[byte & 15];
        }
    }
    return uri;
}

std::string file_name_of_uri(const std::string& uri) {
    const auto digit = [](char c) {
        return c >= '0' && c <= '9'   ? c - '0'
               : c >= 'a' && c <= 'f' ? c - 'a' + 10
               : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                      : -1;
    };
    std::string name;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && digit(uri[i + 1]) >= 0 && digit(uri[i + 2]) >= 0) {
            name += char(digit(uri[i + 1]) * 16 + digit(uri[i + 2]));
            i += 2;
        } else {
            name += uri[i] == '+' ? ' ' : uri[i];
        }
    }
    return name;
}

}  // namespace boxlod
