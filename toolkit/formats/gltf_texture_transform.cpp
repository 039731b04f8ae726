#include "toolkit/formats/gltf_texture_transform.h"

#include "base/input_error.h"
#include "base/key_values.h"
#include "toolkit/formats/gltf_extras.h"

#include <cmath>

namespace boxlod {
namespace {

constexpr NumberRange transform_range{-1e6, 1e6};  // offsets, scales and radians: as CityJSON's uvs

// The extension's number `key`, or element `index` of its pair (its default where absent), checked.
double member_number(const tinygltf::Value& extension, const char* key, int index, double fallback,
                     const std::string& file, const std::string& place) {
    if (!extension.Has(key)) return fallback;
    const tinygltf::Value& member = extension.Get(key);
    const std::string name = std::string(texture_transform_name) + "." + key;
    if (index >= 0 && !(member.IsArray() && member.ArrayLen() == 2))  // tinygltf's Get(int) asserts it
        throw_input_error(file, place, name + ": expected two numbers");
    const tinygltf::Value& value = index < 0 ? member : member.Get(index);
    if (!value.IsNumber()) throw_input_error(file, place, name + ": not a number");
    const double number = value.GetNumberAsDouble();
    if (!transform_range.contains(number))
        throw_input_error(file, place,
                          name + " " + out_of_range_message(transform_range, format_number(number)));
    return number;
}

// The map one extension states, T * R * S of its offset, rotation and scale
// (the extension's spec; the rotation's sign as three.js's GLTFLoader, the
// spec's GLSL listing having it reversed: KhronosGroup/glTF#1563).
UvTransform transform_of(const tinygltf::Value& extension, const std::string& file,
                         const std::string& place) {
    if (!extension.IsObject())
        throw_input_error(file, place, std::string(texture_transform_name) + ": expected an object");
    const double ox = member_number(extension, "offset", 0, 0, file, place),
                 oy = member_number(extension, "offset", 1, 0, file, place),
                 sx = member_number(extension, "scale", 0, 1, file, place),
                 sy = member_number(extension, "scale", 1, 1, file, place),
                 rotation = member_number(extension, "rotation", -1, 0, file, place);
    const double c = std::cos(rotation), s = std::sin(rotation);
    UvTransform m;
    m << sx * c, sy * s, ox, -sx * s, sy * c, oy;
    return m;
}

// The texture infos under a material extension's value (texture infos nest in objects).
void nested_texture_infos(const tinygltf::Value& value, std::vector<const tinygltf::Value*>& out, int depth) {
    if (depth > max_nesting_depth) return;  // the structure check refused deeper JSON
    if (value.IsArray())
        for (std::size_t i = 0; i < value.ArrayLen(); ++i)
            nested_texture_infos(value.Get(int(i)), out, depth + 1);
    if (!value.IsObject()) return;
    if (value.Has("index")) out.push_back(&value);
    for (const std::string& key : value.Keys())
        if (key != "extensions") nested_texture_infos(value.Get(key), out, depth + 1);
}

// The extension of each texture info of material `in` that boxlod draws: base
// colour (unless specular-glossiness' diffuse replaces it), normal, and those
// of the material extensions it reads; nullptr where one has none.
std::vector<const tinygltf::Value*> drawn_transforms(const tinygltf::Material& in) {
    std::vector<const tinygltf::Value*> nested, transforms;
    for (const char* name : {specular_glossiness_name, specular_extension_name})
        if (const auto found = in.extensions.find(name); found != in.extensions.end())
            nested_texture_infos(found->second, nested, 0);
    const auto glossiness = in.extensions.find(specular_glossiness_name);
    const bool diffuse = glossiness != in.extensions.end() && glossiness->second.Has("diffuseTexture");
    const auto add = [&](const tinygltf::ExtensionMap& extensions) {
        const auto found = extensions.find(texture_transform_name);
        transforms.push_back(found == extensions.end() ? nullptr : &found->second);
    };
    if (in.pbrMetallicRoughness.baseColorTexture.index >= 0 && !diffuse)
        add(in.pbrMetallicRoughness.baseColorTexture.extensions);
    if (in.normalTexture.index >= 0) add(in.normalTexture.extensions);
    for (const tinygltf::Value* info : nested) {
        const tinygltf::Value& extensions = info->Get("extensions");
        transforms.push_back(extensions.Has(texture_transform_name) ? &extensions.Get(texture_transform_name)
                                                                    : nullptr);
    }
    return transforms;
}

// The map of the texture infos of material `in` that boxlod draws, none where it is the identity.
std::optional<UvTransform> material_uv_transform(const tinygltf::Material& in, const std::string& file,
                                                 const std::string& place) {
    const UvTransform identity = UvTransform::Identity();
    std::optional<UvTransform> common;
    for (const tinygltf::Value* extension : drawn_transforms(in)) {
        const UvTransform transform = extension ? transform_of(*extension, file, place) : identity;
        if (common && transform != *common)
            throw_input_error(file, place,
                              "its textures are placed by different KHR_texture_transforms (boxlod draws a "
                              "material's textures with one set of texture coordinates)");
        common = transform;
    }
    return common == identity ? std::nullopt : common;
}

}  // namespace

int tex_coord_read(int tex_coord, const tinygltf::ExtensionMap& extensions) {
    const auto found = extensions.find(texture_transform_name);
    if (found == extensions.end() || !found->second.Has("texCoord")) return tex_coord;
    const tinygltf::Value& value = found->second.Get("texCoord");
    return value.IsInt() ? value.GetNumberAsInt() : -1;  // -1: texture_image refuses it
}

int tex_coord_read(const tinygltf::Value& texture_info) {
    const tinygltf::Value& extensions = texture_info.Get("extensions");
    if (extensions.Has(texture_transform_name) && extensions.Get(texture_transform_name).Has("texCoord")) {
        const tinygltf::Value& value = extensions.Get(texture_transform_name).Get("texCoord");
        return value.IsInt() ? value.GetNumberAsInt() : -1;
    }
    if (!texture_info.Has("texCoord")) return 0;
    const tinygltf::Value& value = texture_info.Get("texCoord");
    return value.IsInt() ? value.GetNumberAsInt() : -1;
}

void place_texture_coordinates(const tinygltf::Model& gltf, const std::string& file, Model& model) {
    std::vector<std::optional<UvTransform>> transforms;
    for (std::size_t m = 0; m < gltf.materials.size(); ++m)
        transforms.push_back(material_uv_transform(gltf.materials[m], file, "material " + std::to_string(m)));
    for (Node& node : model.nodes)
        for (Primitive& primitive : node.primitives) {
            if (primitive.material < 0 || !transforms.at(std::size_t(primitive.material))) continue;
            const UvTransform& m = *transforms[std::size_t(primitive.material)];
            for (Eigen::Vector2f& uv : primitive.uvs)
                uv = (m.leftCols<2>() * uv.cast<double>() + m.col(2)).cast<float>();
        }
}

}  // namespace boxlod
