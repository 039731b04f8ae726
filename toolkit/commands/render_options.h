// The options every rendering command shares (camera, size, mode, light,
// overlays) and the settings they produce for a model's bounds.
#pragma once
#include "base/command_line.h"
#include "renderer/renderer.h"
#include "toolkit/model/model.h"

namespace boxlod {

std::vector<Option> render_options();

struct View {
    RenderSettings settings;
    int width = 1024, height = 768;
    Eigen::Vector3f background{1, 1, 1};  // linear
    float distance = 0;
};

// Defaults: camera +X+Y+Z at the distance that frames the model, 1024x768,
// fovy 45, mode normal, light above and behind the camera's right shoulder.
View view_from_arguments(const Arguments& arguments, const Bounds& bounds);

// "R,G,B" (or "X,Y,Z"): three numbers, each in `range`.
constexpr NumberRange colour_range{0, 1};  // sRGB components
Eigen::Vector3f parse_vector3(const std::string& option, const std::string& text, const NumberRange& range);

}  // namespace boxlod
