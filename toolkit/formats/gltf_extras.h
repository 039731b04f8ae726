// boxlod's fields in glTF `extras.boxlod` (docs/design.md: Scene model), one
// schema for export and import: the LoD mark and its parameters on the asset;
// specular colour, shininess and the height texture on a material; rule, scope,
// instance_of and source_id on a node; the polygon count on a primitive. Each writer
// returns a null Value when it has nothing to say; each reader throws
// InputError "FILE: PLACE: what" for a field of the wrong form.
#pragma once
#include "toolkit/model/lod_switch.h"
#include "toolkit/model/model.h"

#include <tiny_gltf.h>

#include <functional>
#include <string>

namespace boxlod {

// The double whose JSON text is the float's shortest form ("0.3", not
// "0.30000001192092896"); read back as float it gives the same float.
double json_number(float value);

tinygltf::Value asset_extras(const Model& model);
tinygltf::Value material_extras(const Material& material, int height_image);  // height_image < 0: none
// A node's extras as JSON text, "" where it has none (tinygltf::Node::extras_json_string);
// a chain's root also says where its levels switch (gltf_io.h: export_gltf_lods).
std::string node_extras_json(const Node& node, const std::vector<LodSwitch>& switches = {});
tinygltf::Value primitive_extras(const Primitive& primitive);
// The node above the scene that carries Model::origin as its translation, and
// Model::reference_system (where not "") as extras.boxlod.reference_system.
tinygltf::Value origin_node_extras(const std::string& reference_system);
bool is_origin_node(const tinygltf::Node& node);  // that node as written: a translation only

// Where a reader is: the file and the place in it ("material 3", "node 7 mesh 2 primitive 0").
struct ExtrasPlace {
    const std::string& file;
    std::string place;
};

// The origin node's reference system, "" without one.
std::string read_origin_reference_system(const tinygltf::Node& node, const ExtrasPlace& at);

void read_asset_extras(const tinygltf::Value& extras, Model& model);
void read_material_extras(const tinygltf::Value& extras, int image_count, const ExtrasPlace& at,
                          Material& material);
void read_node_extras(const tinygltf::Value& extras, const ExtrasPlace& at, Node& node);
void read_primitive_extras(const tinygltf::Value& extras, const ExtrasPlace& at,
                           Primitive& primitive);  // after its indices

// boxlod's texture of a glTF texture index, given the texture info (a material extension's Value) naming it.
using TextureOfInfo = std::function<int(int index, const tinygltf::Value& texture_info)>;

// KHR_materials_pbrSpecularGlossiness (KhronosGroup/glTF, extensions/2.0/Archived)
// for a material with `specular_glossiness`: diffuse = base colour, specular =
// the Phong specular colour, glossiness from the shininess. Texture indices are glTF's (< 0: none).
constexpr const char* specular_glossiness_name = "KHR_materials_pbrSpecularGlossiness";
tinygltf::Value specular_glossiness_extension(const Material& material, int diffuse_texture,
                                              int specular_texture);
// Reads that extension into `material` (every factor in [0, 1] as the extension
// requires).
void read_specular_glossiness(const tinygltf::Value& extension, const ExtrasPlace& at,
                              const TextureOfInfo& texture_image, Material& material);

// KHR_materials_specular (KhronosGroup/glTF, extensions/2.0/Khronos): kept as
// read (Material::specular_extension) and written back; texture indices are glTF's.
constexpr const char* specular_extension_name = "KHR_materials_specular";
tinygltf::Value specular_extension_value(const SpecularExtension& specular, int texture, int color_texture);
SpecularExtension read_specular_extension(const tinygltf::Value& extension, const ExtrasPlace& at,
                                          const TextureOfInfo& texture_image);

// The Blinn-Phong exponent n and glossiness g = 1 - roughness, with
// alpha = roughness^2 and n = 2 / alpha^2 - 2 (B. Karis, "Specular BRDF
// Reference", 2013); n is kept within shininess_range.
float glossiness_of_shininess(float shininess);
float shininess_of_glossiness(float glossiness);

}  // namespace boxlod
