// The geometry of CityJSON objects as boxlod nodes and primitives, for
// toolkit/formats/cityjson_import.cpp (CityJSON 2.0, sections "Geometry
// objects", "Semantics of geometric primitives" and "Appearance object").
#pragma once
#include "toolkit/formats/cityjson_lod.h"
#include "toolkit/formats/cityjson_place.h"
#include "toolkit/model/model.h"

#include <nlohmann/json_fwd.hpp>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace boxlod {

struct CityReadState;  // what the reading has made so far (the .cpp's)

// The largest coordinate a city file may have, in its units: far beyond any
// CRS on Earth, far within what double arithmetic on it keeps finite.
constexpr double max_city_coordinate = 1e12;

// Instances copy their template: memory and time grow as instances x template, which the file's size does
// not bound. A polygon point's share of the model: its vertex, its triangles' indices, its vertex map entry.
constexpr double bytes_per_instanced_point = 160;

// The points a template's surfaces name, repeats counted: what each instance of it copies (0 for a point
// or line template, which draws nothing).
std::size_t city_template_points(const nlohmann::json& shape);

// Reads objects into `model` one document at a time: start_part with the
// document's vertices (in the file's coordinates) and appearance, then
// add_object for each object, parents first; finish says what was left out.
class CityGeometryReader {
public:
    CityGeometryReader(Model& model, const std::string& file, const Eigen::Vector3d& origin);
    ~CityGeometryReader();
    void start_part(const CityPlace& at, const nlohmann::json& document,
                    const std::vector<Eigen::Vector3d>& vertices);
    // A CityJSONSeq's first line's "geometry-templates", for the features
    // without their own (kept by reference).
    void use_file_templates(const nlohmann::json& templates);
    // The object's node under `parent_node`, with its geometry of `lod`
    // ("": its finest) and a child node per semantic surface.
    int add_object(const CityPlace& at, const std::string& id, const nlohmann::json& object, int parent_node,
                   const std::string& lod);
    // Refuses a reading that drew nothing (naming the LoDs the file has);
    // prints one warning line for objects without the LoD and one for missing textures.
    void finish(const std::string& lod) const;

private:
    std::unique_ptr<CityReadState> state_;
};

}  // namespace boxlod
