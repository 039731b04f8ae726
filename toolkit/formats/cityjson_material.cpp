#include "toolkit/formats/cityjson_material.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

namespace boxlod {

using json = nlohmann::json;

namespace {

Eigen::Vector3f colour_of(const CityPlace& at, const json& value, const char* name) {
    if (!value.is_array() || value.size() != 3) at.fail(std::string(name) + " is not three numbers");
    Eigen::Vector3f colour;
    for (int i = 0; i < 3; ++i) {
        if (!value[i].is_number() || !(value[i].get<double>() >= 0 && value[i].get<double>() <= 1))
            at.fail(std::string(name) + " holds " + value[i].dump() + ": colours are in [0, 1]");
        colour[i] = value[i].get<float>();
    }
    return colour;
}

}  // namespace

Material city_material(const CityPlace& at, const json& in, std::size_t index) {
    if (!in.is_object()) at.fail("not an object");
    Material material;
    material.name = in.contains("name") && in["name"].is_string() ? in["name"].get<std::string>()
                                                                  : "material " + std::to_string(index);
    material.base_color.head<3>() = in.contains("diffuseColor")
                                        ? colour_of(at, in["diffuseColor"], "diffuseColor")
                                        : Eigen::Vector3f(0.8f, 0.8f, 0.8f);  // X3D's default
    if (in.contains("transparency")) {
        const json& t = in["transparency"];
        if (!t.is_number() || !(t.get<double>() >= 0 && t.get<double>() <= 1))
            at.fail("transparency is not in [0, 1]");
        material.base_color[3] = 1 - t.get<float>();
        if (material.base_color[3] < 1) material.alpha_mode = AlphaMode::blend;
    }
    if (in.contains("specularColor")) {
        material.specular_color = colour_of(at, in["specularColor"], "specularColor");
        material.specular_glossiness = true;
    }
    if (in.contains("shininess") && in["shininess"].is_number())
        material.shininess = std::clamp(in["shininess"].get<float>(), 0.0f, 1.0f) * 128 + 1;
    return material;
}

}  // namespace boxlod
