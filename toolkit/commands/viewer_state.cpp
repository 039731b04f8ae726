#include "toolkit/commands/viewer_state.h"

#include "base/input_error.h"
#include "base/number_text.h"
#include "toolkit/model/framing.h"
#include "toolkit/model/statistics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace boxlod {
namespace {

// Near and far follow the camera so the model is never clipped; so does the default light.
void camera_moved(ViewerState& s) {
    Camera& c = s.settings.camera;
    if (s.light_follows_camera) s.settings.light.position = light_for_camera(c).position;
    const Framing framing = model_framing(*s.model);
    fit_depth_range(c, (c.position - framing.center).norm(), framing.radius);
}

void parameters_changed(ViewerState& s, const std::string& message) {
    s.needs_update = true;
    s.message = message;
}

}  // namespace

ViewerState make_viewer_state(const Model& model, const LodParameters& parameters,
                              const RenderSettings& settings, int width, int height,
                              const Eigen::Vector3f& background) {
    ViewerState s;
    s.model = &model;
    s.parameters = parameters;
    s.settings = settings;
    s.width = width;
    s.height = height;
    s.background = background;
    s.original_drawable = make_drawable_model(model);
    return s;
}

namespace {

// What a key press sees: the state and the camera's frame at that moment.
struct KeyPress {
    ViewerState& s;
    Camera& camera;
    Eigen::Vector3f forward, right;
    float distance;
    const std::string& key;
};

// The viewer's keys, one row each: the SDL names it answers to, its label
// and help (viewer_key_help), and what it does; true when the picture changes.
struct ViewerKey {
    std::vector<std::string> names;
    const char* label;
    const char* help;
    bool (*action)(KeyPress&);
};

bool cycle_lod_parameter(ViewerState& s, const std::string& message) {
    s.chain.reset();
    parameters_changed(s, message);
    return true;
}

bool move(KeyPress& p, const Eigen::Vector3f& direction) {
    Eigen::Vector3f step = direction * (std::max(p.distance, 1e-6f) * 0.05f);
    p.camera.position += step;
    p.camera.target += step;
    return true;
}

bool request(bool& flag) {  // for the front end: a file to write or read, or quitting
    flag = true;
    return false;
}

const std::vector<ViewerKey>& viewer_keys() {
    static const std::vector<ViewerKey> keys = {
        {{"w", "s"},
         "W/S",
         "forward, back",
         [](KeyPress& p) { return move(p, p.key == "w" ? p.forward : -p.forward); }},
        {{"a", "d"},
         "A/D",
         "left, right",
         [](KeyPress& p) { return move(p, p.key == "d" ? p.right : -p.right); }},
        {{"c"},
         "C",
         "next of the 26 camera positions",
         [](KeyPress& p) {
             std::vector<std::string> names = camera_position_names();
             p.s.camera_position = (p.s.camera_position + 1) % int(names.size());
             p.camera =
                 framed_camera(model_framing(*p.s.model), *camera_direction(names[p.s.camera_position]),
                               p.distance, p.camera.fovy_degrees);
             p.s.message = "camera " + names[p.s.camera_position];
             return true;
         }},
        {{"m"},
         "M",
         "render mode",
         [](KeyPress& p) {
             ViewerState& s = p.s;
             s.settings.mode = next_enum(render_modes(), s.settings.mode);
             if (s.parameters.render_mode == RenderMode::untextured ||
                 s.settings.mode == RenderMode::untextured)
                 parameters_changed(s, "");  // untextured LoDs are not baked
             s.parameters.render_mode = s.settings.mode;
             s.message = std::string("render mode ") + render_mode_name(s.settings.mode);
             return true;
         }},
        {{"f"},
         "F",
         "wireframe",
         [](KeyPress& p) { return p.s.settings.wireframe = !p.s.settings.wireframe, true; }},
        {{"x"}, "X", "coordinate cross", [](KeyPress& p) { return p.s.axes = !p.s.axes, true; }},
        {{"v"},
         "V",
         "split view (LoD left, original right)",
         [](KeyPress& p) { return p.s.split_view = !p.s.split_view, true; }},
        {{"+", "=", "keypad +"},
         "+",
         "current level up",
         [](KeyPress& p) {
             ++p.s.parameters.current_level;
             parameters_changed(p.s, "level up");
             return true;
         }},
        {{"-", "keypad -"},
         "-",
         "current level down",
         [](KeyPress& p) {
             p.s.parameters.current_level = std::max(0, p.s.parameters.current_level - 1);
             parameters_changed(p.s, "level down");
             return true;
         }},
        {{"l"},
         "L",
         "level mode",
         [](KeyPress& p) {
             p.s.parameters.level_mode = next_enum(level_modes(), p.s.parameters.level_mode);
             return cycle_lod_parameter(
                 p.s, std::string("level mode ") + level_mode_name(p.s.parameters.level_mode));
         }},
        {{"b"},
         "B",
         "box kind",
         [](KeyPress& p) {
             p.s.parameters.box_kind = next_enum(box_kinds(), p.s.parameters.box_kind);
             return cycle_lod_parameter(p.s,
                                        std::string("box kind ") + box_kind_name(p.s.parameters.box_kind));
         }},
        {{"i"},
         "I",
         "interpolation",
         [](KeyPress& p) {
             p.s.parameters.interpolation = next_enum(interpolations(), p.s.parameters.interpolation);
             return cycle_lod_parameter(
                 p.s, std::string("interpolation ") + interpolation_name(p.s.parameters.interpolation));
         }},
        {{"u"},
         "U",
         "update",
         [](KeyPress& p) {
             p.s.needs_update = p.s.update_now = true;
             p.s.message = "update";
             return true;
         }},
        {{"y"},
         "Y",
         "auto-update",
         [](KeyPress& p) {
             p.s.auto_update = !p.s.auto_update;
             p.s.message = p.s.auto_update ? "auto-update on" : "auto-update off";
             return true;
         }},
        {{"t"},
         "T",
         "show the LoD texture",
         [](KeyPress& p) { return p.s.show_texture = !p.s.show_texture, true; }},
        {{"p"},
         "P",
         "next page",
         [](KeyPress& p) {
             ViewerState& s = p.s;
             s.texture_page = s.lod && !s.lod->atlas.pages.empty()
                                  ? (s.texture_page + 1) % int(s.lod->atlas.pages.size())
                                  : 0;
             return true;
         }},
        {{"[", "]"},
         "[ ]",
         "texture scale",
         [](KeyPress& p) { return p.s.texture_scale *= p.key == "]" ? 2.0f : 0.5f, true; }},
        {{"tab"},
         "Tab",
         "statistics",
         [](KeyPress& p) { return p.s.show_statistics = !p.s.show_statistics, true; }},
        {{"g"},
         "G",
         "light follows the camera or stays",
         [](KeyPress& p) {
             p.s.light_follows_camera = !p.s.light_follows_camera;
             p.s.message = p.s.light_follows_camera ? "light follows the camera" : "light fixed";
             return true;
         }},
        {{"1", "2", "3", "4", "5", "6", "7", "8"},
         "1/2 3/4 5/6 7/8",
         "ambient, diffuse, specular, shininess down/up",
         [](KeyPress& p) {
             Light& light = p.s.settings.light;
             int option = (p.key[0] - '1') / 2;
             float factor = (p.key[0] - '1') % 2 ? 1.25f : 0.8f;
             float* values[4] = {&light.ambient, &light.diffuse, &light.specular, &light.shininess};
             if (option == 3 && light.shininess == 0)
                 light.shininess = 32;  // start from the usual material value
             *values[option] *= factor;
             const char* names[4] = {"ambient", "diffuse", "specular", "shininess"};
             p.s.message = std::string(names[option]) + " " + format_number(*values[option]);
             return true;
         }},
        // The manual's Get Distance: the camera's distance becomes the sizing distance.
        {{"h"},
         "H",
         "get the sizing distance",
         [](KeyPress& p) {
             p.s.parameters.distance = p.distance;
             return cycle_lod_parameter(p.s, "sizing distance " + format_number(p.distance));
         }},
        // The manual's Set Distance: the camera moves to the sizing distance.
        {{"n"},
         "N",
         "set the sizing distance",
         [](KeyPress& p) {
             float wanted = p.s.parameters.distance > 0
                                ? p.s.parameters.distance
                                : framing_distance(model_framing(*p.s.model), p.camera.fovy_degrees);
             p.camera.position = p.camera.target - p.forward * wanted;
             p.s.message = "distance " + format_number(wanted);
             return true;
         }},
        {{"f12"}, "F12", "screenshot", [](KeyPress& p) { return request(p.s.screenshot); }},
        {{"f5"}, "F5", "save parameters", [](KeyPress& p) { return request(p.s.save_parameters); }},
        {{"f9"}, "F9", "load parameters", [](KeyPress& p) { return request(p.s.load_parameters); }},
        {{"f6"}, "F6", "export the LoD", [](KeyPress& p) { return request(p.s.export_lod); }},
        {{"q", "escape"}, "Q/Escape", "quit", [](KeyPress& p) { return request(p.s.quit); }},
    };
    return keys;
}

}  // namespace

std::string viewer_key_help() {
    std::string help = "left-drag: orbit, wheel: distance";
    for (const ViewerKey& key : viewer_keys()) help += std::string(", ") + key.label + ": " + key.help;
    return help;
}

bool apply_event(ViewerState& s, const ViewerEvent& e) {
    Camera& camera = s.settings.camera;
    Eigen::Vector3f forward = (camera.target - camera.position).normalized();
    Eigen::Vector3f right = forward.cross(camera.up).normalized();
    float distance = (camera.target - camera.position).norm();
    if (e.kind == ViewerEvent::Kind::drag) {
        // Orbit about the target: yaw about world up, pitch about the camera's right axis.
        Eigen::Vector3f offset = camera.position - camera.target;
        Eigen::AngleAxisf yaw(-e.dx * 0.01f, Eigen::Vector3f::UnitY());
        Eigen::AngleAxisf pitch(-e.dy * 0.01f, right);
        Eigen::Vector3f turned = pitch * (yaw * offset);
        if (std::abs(turned.normalized().dot(camera.up)) < 0.995f)
            offset = turned;  // not over the pole
        else
            offset = yaw * offset;
        camera.position = camera.target + offset;
        camera_moved(s);
        return true;
    }
    if (e.kind == ViewerEvent::Kind::wheel) {
        // Never at infinity nor at the target, however many steps out or in (the target is the model's).
        const float wheeled =
            std::clamp(distance * std::pow(0.9f, e.dy), float(parameter_range::min_positive_distance),
                       float(parameter_range::position.max) / 2);
        camera.position = camera.target - forward * wheeled;
        camera_moved(s);
        return true;
    }
    for (const ViewerKey& key : viewer_keys()) {
        if (std::find(key.names.begin(), key.names.end(), e.key) == key.names.end()) continue;
        KeyPress press{s, camera, forward, right, distance, e.key};
        if (!key.action(press)) return false;
        camera_moved(s);
        return true;
    }
    return false;
}

Frame render_view(ViewerState& s, int threads) {
    s.settings.threads = threads;
    bool rebuild = s.needs_update && (s.auto_update || s.update_now);
    s.update_now = false;
    if (rebuild && !s.model->is_lod) {
        s.lod.reset();
        s.lod_drawable.reset();
        if (s.parameters.current_level > 0) {
            if (!s.chain) s.chain = std::make_unique<Chain>(*s.model, s.parameters, threads);
            s.parameters.current_level = std::min(s.parameters.current_level, s.chain->obtained_levels());
            s.lod = std::make_unique<Lod>(s.chain->build(s.parameters.current_level));
            s.lod_drawable = make_drawable_model(s.lod->model);
        }
        s.needs_update = false;
    }
    const Drawable& shown = s.lod_drawable ? s.lod_drawable->drawable : s.original_drawable->drawable;
    Frame frame = make_frame(s.width, s.height, s.background);
    if (s.split_view) {
        RenderSettings left = s.settings, right = s.settings;
        left.scissor_x1 = s.width / 2;
        right.scissor_x0 = s.width / 2;
        render(shown.batches, left, frame);
        render(s.original_drawable->drawable.batches, right, frame);
    } else {
        render(shown.batches, s.settings, frame);
    }
    return frame;
}

std::vector<std::string> overlay_lines(const ViewerState& s) {
    std::vector<std::string> lines;
    const Camera& c = s.settings.camera;
    std::ostringstream view;
    view << "mode " << render_mode_name(s.settings.mode) << "  distance "
         << format_number((c.position - c.target).norm()) << (s.settings.wireframe ? "  wireframe" : "")
         << (s.split_view ? "  split view" : "");
    lines.push_back(view.str());
    std::ostringstream lod;
    lod << "level " << s.parameters.current_level;
    if (s.chain) lod << " of " << s.chain->obtained_levels();
    lod << "  " << level_mode_name(s.parameters.level_mode) << "  box "
        << box_kind_name(s.parameters.box_kind) << (s.auto_update ? "  auto-update" : "  (U: update)")
        << (s.needs_update ? "  *changed*" : "");
    lines.push_back(s.model->is_lod ? "an exported LoD (view only)" : lod.str());
    if (s.show_statistics) {
        KeyValues statistics = s.lod ? s.lod->statistics : model_statistics(*s.model);
        for (const KeyValue& e : statistics) lines.push_back(e.key + " = " + e.value);
    }
    if (!s.message.empty()) lines.push_back(s.message);
    return lines;
}

std::optional<ViewerEvent> parse_replay_line(const std::string& line, const std::string& file, int number) {
    std::istringstream in(line.substr(0, line.find('#')));
    std::string word;
    if (!(in >> word)) return std::nullopt;
    ViewerEvent e;
    auto fail = [&](const std::string& what) {
        throw_input_error(file, "line " + std::to_string(number), what);
    };
    // A drag within a screen's pixels, a wheel within 100 steps (0.9^100 of the distance): SDL's ints.
    auto read_number = [&](const char* form, const char* name, const NumberRange& range, float& value) {
        std::string text;
        if (!(in >> text)) fail(std::string("expected '") + form + "'");
        const auto v = number_within<float>(text, range);
        if (!v) fail(std::string(name) + ": " + number_problem<float>(text, range));
        value = *v;
    };
    if (word == "key") {
        if (!(in >> e.key)) fail("expected 'key NAME'");
        for (char& ch : e.key) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    } else if (word == "drag") {
        e.kind = ViewerEvent::Kind::drag;
        read_number("drag DX DY", "DX", replay_drag_range, e.dx);
        read_number("drag DX DY", "DY", replay_drag_range, e.dy);
    } else if (word == "wheel") {
        e.kind = ViewerEvent::Kind::wheel;
        read_number("wheel N", "N", replay_wheel_range, e.dy);
    } else {
        fail("unknown event '" + word + "' (key, drag, wheel)");
    }
    std::string extra;
    if (in >> extra) fail("unexpected '" + extra + "'");
    return e;
}

}  // namespace boxlod
