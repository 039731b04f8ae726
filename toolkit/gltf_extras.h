// boxlod's fields in glTF `extras.boxlod` (docs/design.md: Scene model), one
// schema for export and import: the LoD mark and its parameters on the asset;
// specular colour, shininess and the height texture on a material; rule, scope
// and instance_of on a node; the polygon count on a primitive. Each writer
// returns a null Value when it has nothing to say; each reader throws
// InputError "FILE: PLACE: what" for a field of the wrong form.
#pragma once
#include "toolkit/model.h"

#include <tiny_gltf.h>

#include <string>

namespace boxlod {

// The double whose JSON text is the float's shortest form ("0.3", not
// "0.30000001192092896"); read back as float it gives the same float.
double json_number(float value);

tinygltf::Value asset_extras(const Model& model);
tinygltf::Value material_extras(const Material& material, int height_image);  // height_image < 0: none
tinygltf::Value node_extras(const Node& node);
tinygltf::Value primitive_extras(const Primitive& primitive);

// Where a reader is: the file and the place in it ("material 3", "node 7 mesh 2 primitive 0").
struct ExtrasPlace {
    const std::string& file;
    std::string place;
};

void read_asset_extras(const tinygltf::Value& extras, Model& model);
void read_material_extras(const tinygltf::Value& extras, int image_count, const ExtrasPlace& at, Material& material);
void read_node_extras(const tinygltf::Value& extras, const ExtrasPlace& at, Node& node);
void read_primitive_extras(const tinygltf::Value& extras, const ExtrasPlace& at, Primitive& primitive);  // after its indices

}  // namespace boxlod
