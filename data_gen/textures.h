// Procedural textures for the built-in materials: brick, plaster, roof tiles,
// glass, wood and stone. Each is a seamless tile made deterministically from
// hashed value noise: an sRGB colour image and a matching tangent-space
// normal map (+X right, +Y up in the image, encoded n * 0.5 + 0.5).
#pragma once
#include "renderer/image.h"

#include <string>

namespace boxlod {

struct ProceduralTexture {
    Image8 color;           // RGBA8, sRGB
    Image8 normal;          // RGBA8, linear
    float tile_metres = 1;  // the size of one tile on a surface
};

bool is_texture_name(const std::string& name);
std::string texture_names();  // "brick, plaster, roof_tiles, glass, wood, stone"

// Metres covered by one tile of the named texture on a surface.
float texture_tile_metres(const std::string& name);

// `size` x `size` texels; the same name and size give the same pixels.
ProceduralTexture procedural_texture(const std::string& name, int size = 128);

}  // namespace boxlod
