// KHR_texture_transform: a texture placed by an affine map of its texture
// coordinates. boxlod draws a material's textures with one set of
// coordinates (TEXCOORD_0), so the import applies a material's map to the
// coordinates of the primitives drawn with it, and the export writes them so.
#pragma once
#include <tiny_gltf.h>
#include "toolkit/model/model.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace boxlod {

constexpr const char* texture_transform_name = "KHR_texture_transform";
using UvTransform = Eigen::Matrix<double, 2, 3>;  // uv' = M * (u, v, 1)

// The texture coordinate set a texture info reads: its texCoord, or the one the extension overrides it with;
// -1 where one is not a whole number. As tinygltf reads the info, or as a material extension's Value.
int tex_coord_read(int tex_coord, const tinygltf::ExtensionMap& extensions);
int tex_coord_read(const tinygltf::Value& texture_info);

// Each primitive's coordinates placed by the map of its material's texture
// infos that boxlod draws (base colour, normal, and those of the material
// extensions it reads); `model` as read from `gltf`, material for material.
// Throws InputError naming `file` and the material where the maps differ or a
// value lies outside its range.
void place_texture_coordinates(const tinygltf::Model& gltf, const std::string& file, Model& model);

}  // namespace boxlod
