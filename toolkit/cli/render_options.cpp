#include "toolkit/cli/render_options.h"

#include "renderer/input_error.h"

#include <Eigen/Geometry>
#include <charconv>
#include <cmath>

namespace boxlod {

std::vector<Option> render_options() {
    return {
        {"camera", "POS", "one of the 26 camera positions, e.g. +X+Y+Z (default), -Z, +Y"},
        {"distance", "D", "camera distance from the model's centre (default: frames the model)"},
        {"fovy", "DEG", "vertical field of view in degrees (default 45)"},
        {"width", "W", "image width in pixels (default 1024)"},
        {"height", "H", "image height in pixels (default 768)"},
        {"mode", "MODE", "untextured | normal (default) | parallax | pom | albedo"},
        {"parallax-scale", "S", "parallax/pom height scale (default 0.04)"},
        {"parallax-bias", "B", "parallax height bias (default -0.02)"},
        {"light", "X,Y,Z", "light position in world space (default: above, right of the camera)"},
        {"ambient", "A", "ambient light (default 0.25)"},
        {"diffuse", "D", "diffuse light (default 0.75)"},
        {"specular", "S", "specular light (default 0.25)"},
        {"shininess", "N", "shininess for every material (default: the materials' own)"},
        {"background", "R,G,B", "background colour, sRGB components in [0, 1] (default 1,1,1)"},
        {"cull", "FACES", "none (default) | back | front"},
        {"wireframe", "", "draw triangle edges over the shaded image"},
        {"threads", "N", "threads to use (default: all cores)"},
    };
}

Eigen::Vector3f parse_vector3(const std::string& option, const std::string& text) {
    Eigen::Vector3f v;
    const char* p = text.data();
    const char* end = text.data() + text.size();
    for (int i = 0; i < 3; ++i) {
        auto [next, error] = std::from_chars(p, end, v[i]);
        if (error != std::errc() || !std::isfinite(v[i])) break;
        p = next;
        if (i < 2) {
            if (p == end || *p != ',') break;
            ++p;
        } else if (p == end) {
            return v;
        }
    }
    throw InputError("--" + option + ": expected three numbers X,Y,Z, got '" + text + "'");
}

View view_from_arguments(const Arguments& a, const Bounds& bounds) {
    View view;
    view.width = a.integer("width", 1024);
    view.height = a.integer("height", 768);
    if (view.width < 1 || view.height < 1 || view.width > 16384 || view.height > 16384)
        throw InputError("--width/--height: image size must be 1..16384 pixels");
    float fovy = float(a.number("fovy", 45));
    if (!(fovy > 0 && fovy < 180)) throw InputError("--fovy: expected degrees in (0, 180)");
    std::string position = a.text("camera", "+X+Y+Z");
    auto direction = camera_direction(position);
    if (!direction) throw InputError("--camera: unknown camera position '" + position + "' (e.g. +X, -Y, +X+Y+Z)");
    Eigen::Vector3f center = bounds.center();
    float radius = std::max(bounds.size().norm() / 2, 1e-6f);
    view.distance = float(a.number("distance", framing_distance(radius, fovy)));
    if (!(view.distance > 0)) throw InputError("--distance: expected a positive distance");
    RenderSettings& s = view.settings;
    s.camera = camera_at_position(*direction, center, view.distance, fovy, radius);
    if (a.has("mode") && !parse_render_mode(a.text("mode"), s.mode))
        throw InputError("--mode: unknown render mode '" + a.text("mode") + "' (untextured, normal, parallax, pom, albedo)");
    s.parallax_scale = float(a.number("parallax-scale", s.parallax_scale));
    s.parallax_bias = float(a.number("parallax-bias", s.parallax_bias));
    s.light = light_for_camera(s.camera);
    if (a.has("light")) s.light.position = parse_vector3("light", a.text("light"));
    s.light.ambient = float(a.number("ambient", s.light.ambient));
    s.light.diffuse = float(a.number("diffuse", s.light.diffuse));
    s.light.specular = float(a.number("specular", s.light.specular));
    s.light.shininess = float(a.number("shininess", 0));
    if (a.has("background")) {
        Eigen::Vector3f srgb = parse_vector3("background", a.text("background"));
        for (int c = 0; c < 3; ++c) view.background[c] = srgb_to_linear(std::uint8_t(std::lround(std::clamp(srgb[c], 0.0f, 1.0f) * 255)));
    }
    std::string cull = a.text("cull", "none");
    if (cull == "back") s.culling = Culling::back;
    else if (cull == "front") s.culling = Culling::front;
    else if (cull != "none") throw InputError("--cull: expected none, back or front");
    s.wireframe = a.has("wireframe");
    s.threads = a.integer("threads", 0);
    if (s.threads < 0) throw InputError("--threads: expected a positive count");
    return view;
}

}  // namespace boxlod
