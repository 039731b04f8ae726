#include "toolkit/formats/gltf_texture_transform.h"

#include "base/input_error.h"
#include "toolkit/formats/gltf_extras.h"

#include <cmath>

namespace boxlod {
namespace {

constexpr NumberRange transform_range{-1e6, 1e6};  // offsets, scales and radians: as CityJSON's uvs

// The extension's number `key` (its default where absent), checked.
double member_number(const tinygltf::Value& extension, const char* key, int index, double fallback,
                     const std::string& file, const std::string& place) {
    if (!extension.Has(key)) return fallback;
    const tinygltf::Value& value = index < 0 ? extension.Get(key) : extension.Get(key).Get(index);
    const double number = value.IsNumber() ? value.GetNumberAsDouble() : NAN;
    if (!transform_range.contains(number))
        throw_input_error(file, place,
                          std::string(texture_transform_name) + "." + key + " " +
                              out_of_range_message(transform_range, std::to_string(number)));
    return number;
}

// The map one extension states: T * R * S of its offset, rotation and scale
// (the extension's spec, with the rotation's sign as three.js's GLTFLoader).
UvTransform transform_of(const tinygltf::Value& extension, const std::string& file,
                         const std::string& place) {
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

// Every texture info's extension map under a material extension's value (texture infos nest in objects).
void texture_info_extensions(const tinygltf::Value& value, std::vector<const tinygltf::Value*>& out,
                             int depth) {
    if (depth > max_nesting_depth) return;  // the structure check refused deeper JSON
    if (value.IsArray())
        for (std::size_t i = 0; i < value.ArrayLen(); ++i)
            texture_info_extensions(value.Get(int(i)), out, depth + 1);
    if (!value.IsObject()) return;
    if (value.Has("index")) out.push_back(&value);
    for (const std::string& key : value.Keys())
        if (key != "extensions") texture_info_extensions(value.Get(key), out, depth + 1);
}

// The map of the texture infos of material `in` that boxlod draws, none where none has one.
std::optional<UvTransform> material_uv_transform(const tinygltf::Material& in, const std::string& file,
                                                 const std::string& place) {
    std::vector<std::pair<int, const tinygltf::ExtensionMap*>> infos = {
        {in.pbrMetallicRoughness.baseColorTexture.index,
         &in.pbrMetallicRoughness.baseColorTexture.extensions},
        {in.normalTexture.index, &in.normalTexture.extensions}};
    std::vector<const tinygltf::Value*> nested;
    for (const char* name : {specular_glossiness_name, specular_extension_name})
        if (const auto found = in.extensions.find(name); found != in.extensions.end())
            texture_info_extensions(found->second, nested, 0);
    std::vector<std::optional<UvTransform>> transforms;
    for (const auto& [index, extensions] : infos)
        if (index >= 0) {
            const auto found = extensions->find(texture_transform_name);
            transforms.push_back(found == extensions->end()
                                     ? std::nullopt
                                     : std::optional(transform_of(found->second, file, place)));
        }
    for (const tinygltf::Value* info : nested) {
        const tinygltf::Value& extensions = info->Get("extensions");
        transforms.push_back(
            extensions.Has(texture_transform_name)
                ? std::optional(transform_of(extensions.Get(texture_transform_name), file, place))
                : std::nullopt);
    }
    for (const auto& transform : transforms)
        if (transform != transforms.front())
            throw_input_error(file, place,
                              "its textures are placed by different KHR_texture_transforms (boxlod draws a "
                              "material's textures with one set of texture coordinates)");
    return transforms.empty() ? std::nullopt : transforms.front();
}

}  // namespace

int tex_coord_read(int tex_coord, const tinygltf::ExtensionMap& extensions) {
    const auto found = extensions.find(texture_transform_name);
    if (found == extensions.end() || !found->second.Has("texCoord")) return tex_coord;
    const tinygltf::Value& value = found->second.Get("texCoord");
    return value.IsInt() ? value.GetNumberAsInt() : -1;  // -1: texture_image refuses it
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
