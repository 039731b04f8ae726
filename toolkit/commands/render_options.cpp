#include "toolkit/commands/render_options.h"

#include "base/common_options.h"
#include "base/input_error.h"
#include "base/memory_budget.h"
#include "base/parallel.h"
#include "renderer/image.h"
#include "toolkit/commands/lod_options.h"
#include "toolkit/lod/parameter_file.h"
#include "toolkit/model/framing.h"

#include <Eigen/Geometry>
#include <charconv>
#include <cmath>

namespace boxlod {
std::vector<Option> render_options() {
    return with_options(
        {
            {"camera", "POS", "one of the 26 camera positions, e.g. +X+Y+Z, -Z, +Y", std::nullopt, "+X+Y+Z"},
            {"distance", "D", "camera distance from the model's centre (default: frames the model)",
             NumberRange{1e-3, 1e6}},
            {"fovy", "DEG", "vertical field of view in degrees", parameter_range::fovy,
             format_number(LodParameters{}.fovy)},
            {"width", "W", "image width in pixels", image_side_range, "1024"},
            {"height", "H", "image height in pixels", image_side_range, "768"},
            {"mode", "MODE", enum_names(render_modes(), ", ", " or "), std::nullopt,
             render_mode_name(RenderSettings{}.mode)},
            {"light", "X,Y,Z", "light position in world space (default: above, right of the camera)"},
            {"ambient", "A", "ambient light", light_intensity_range, format_number(Light{}.ambient)},
            {"diffuse", "D", "diffuse light", light_intensity_range, format_number(Light{}.diffuse)},
            {"specular", "S", "specular light", light_intensity_range, format_number(Light{}.specular)},
            {"shininess", "N", "shininess for every material (default: the materials' own)", shininess_range},
            {"background", "R,G,B", "background colour, sRGB components in [0, 1]", std::nullopt, "1,1,1"},
            {"cull", "FACES", "none, back or front", std::nullopt, "none"},
            {"wireframe", "", "draw triangle edges over the shaded image"},
            threads_option(),
        },
        lod_options({"parallax_scale", "parallax_bias"}));
}

Eigen::Vector3f parse_vector3(const std::string& option, const std::string& text, const NumberRange& range) {
    Eigen::Vector3f v;
    const char* p = text.data();
    const char* end = text.data() + text.size();
    for (int i = 0; i < 3; ++i) {
        auto [next, error] = std::from_chars(p, end, v[i]);
        if (error != std::errc() || !range.contains(v[i])) break;
        p = next;
        if (i < 2) {
            if (p == end || *p != ',') break;
            ++p;
        } else if (p == end) {
            return v;
        }
    }
    throw InputError("--" + option + ": expected three numbers X,Y,Z, each " +
                     out_of_range_message(range, text).substr(9));
}

View view_from_arguments(const Arguments& a, const Bounds& bounds) {
    View view;
    view.width = a.integer("width");
    view.height = a.integer("height");
    check_memory(
        "--width " + std::to_string(view.width) + " --height " + std::to_string(view.height) + ": the image",
        render_memory(view.width, view.height));
    const float fovy = float(a.number("fovy"));
    const std::string position = a.text("camera");
    auto direction = camera_direction(position);
    if (!direction)
        throw InputError("--camera: unknown camera position '" + position + "' (e.g. +X, -Y, +X+Y+Z)");
    Framing framing = framing_of(bounds);
    view.distance = float(a.number("distance", framing_distance(framing, fovy)));
    RenderSettings& s = view.settings;
    s.camera = framed_camera(framing, *direction, view.distance, fovy);
    if (!parse_render_mode(a.text("mode"), s.mode))
        throw InputError("--mode: unknown render mode '" + a.text("mode") + "' (" +
                         enum_names(render_modes()) + ")");
    LodParameters parallax;
    apply_lod_options(a, parallax, {"parallax_scale", "parallax_bias"});
    s.parallax_scale = parallax.parallax_scale;
    s.parallax_bias = parallax.parallax_bias;
    s.light = light_for_camera(s.camera);
    if (a.has("light")) s.light.position = parse_vector3("light", a.text("light"), parameter_range::position);
    s.light.ambient = float(a.number("ambient"));
    s.light.diffuse = float(a.number("diffuse"));
    s.light.specular = float(a.number("specular"));
    s.light.shininess = float(a.number("shininess", 0));
    const Eigen::Vector3f srgb = parse_vector3("background", a.text("background"), colour_range);
    for (int c = 0; c < 3; ++c) view.background[c] = srgb_to_linear(std::uint8_t(std::lround(srgb[c] * 255)));
    const std::string cull = a.text("cull");
    if (cull == "back")
        s.culling = Culling::back;
    else if (cull == "front")
        s.culling = Culling::front;
    else if (cull != "none")
        throw InputError("--cull: expected none, back or front");
    s.wireframe = a.has("wireframe");
    s.threads = threads_from(a);
    return view;
}

}  // namespace boxlod
