// Which geometries of a CityJSON object a reading of one LoD draws (CityJSON
// 2.0, "Geometry objects": each geometry states its "lod", a string such as
// "2.2", or a number in older files).
#pragma once
#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace boxlod {

// The LoD of a geometry as the file spells it (numbers as their shortest
// text: 2 -> "2"), "" without one; and as a number (-1 if it is none: the
// whole text a number in [0, 4], CityGML 2.0's LoD 0 to 4 and TU Delft's
// refinements such as 2.2).
std::string city_geometry_lod(const nlohmann::json& geometry);
double city_lod_number(const std::string& lod);

// The indices of the object's `geometries` (an array) that reading `lod` draws: those of that LoD (2 and
// "2.0" alike), or for "" those of the object's finest; of one spelling ("2.2" and "2.20" of one object
// are one LoD twice): `lod`'s if one is spelt so, else the first's.
std::vector<std::size_t> city_geometries_of_lod(const nlohmann::json& geometries, const std::string& lod);

}  // namespace boxlod
