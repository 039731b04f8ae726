// The colour a CityJSON surface is drawn in when it names neither a material
// nor a texture: its semantic type's (linear RGB; the shades city viewers
// commonly use), so that a roof reads as a roof in an untextured model such
// as 3DBAG's (cityjson_geometry.h).
#pragma once
#include <Eigen/Core>

#include <string>

namespace boxlod {

// A semantic surface type's colour ("RoofSurface", "Window", ...); a light
// grey for a type without one or none.
Eigen::Vector3f semantic_colour(const std::string& type);

}  // namespace boxlod
