// The far-distance LoD of game engines as a baseline (docs/sweeps.md): an
// octahedral impostor. The model is captured orthographically from K x K
// directions of a hemi-octahedral grid into one square atlas of K x K cells,
// colour with coverage and a tangent-space normal map, each cell baked as a
// box face is (toolkit/lod/pages/bake.h). It is drawn as one quad through the centre of
// the model's bounding sphere, in the capture plane of the direction nearest
// the camera, textured with that direction's cell.
#pragma once
#include "toolkit/lod/pages/bake.h"
#include "toolkit/model/model.h"

#include <vector>

namespace boxlod {

struct ImpostorAtlas {
    int directions_per_side = 0;          // K
    int cell = 0;                         // texels per cell side
    std::vector<OrientedBoxFace> frames;  // per cell, row-major; normal = the direction towards the viewer
    Image8 color, normal;                 // K x cell texels square
};

constexpr int max_impostor_directions = 32;

// The direction of grid point g in [-1, 1]^2 on the upper (y >= 0) hemisphere:
// the hemi-octahedral map (Cigolle et al. 2014, "A Survey of Efficient
// Representations for Independent Unit Vectors", JCGT 3(2), section 3.2),
// its square turned 45 degrees so that it fills [-1, 1]^2.
Eigen::Vector3f hemi_octahedral_direction(const Eigen::Vector2f& grid);

// Texels per cell for texel = pixel: the bounding sphere's diameter in texels of
// `texel_size` world units, plus the margins, within [8, 2048].
int impostor_cell(const Bounds& bounds, double texel_size);

// `directions_per_side` in [2, max_impostor_directions], `cell` texels per cell in [8, 2048].
ImpostorAtlas make_impostor(const Model& model, int directions_per_side, int cell, int threads);

// The cell whose direction is nearest the direction from the model's centre to `eye`.
int nearest_direction(const ImpostorAtlas& atlas, const Eigen::Vector3f& eye);

// The impostor as drawn from `eye`: one quad, one material (the atlas, alpha cut out).
Model impostor_model(const ImpostorAtlas& atlas, const Eigen::Vector3f& eye, const std::string& source);

}  // namespace boxlod
