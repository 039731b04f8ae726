// A CityJSON appearance material (X3D's terms) as boxlod's: diffuse colour,
// transparency (blended), specular colour and shininess (X3D scales it by
// 128); a colour outside [0, 1] is refused at its place.
#pragma once
#include "toolkit/formats/cityjson_place.h"
#include "toolkit/model/model.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>

namespace boxlod {

// Appearance material `index` (its name when it has none).
Material city_material(const CityPlace& at, const nlohmann::json& in, std::size_t index);

}  // namespace boxlod
