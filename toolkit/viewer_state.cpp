#include "toolkit/viewer_state.h"

#include "renderer/input_error.h"
#include "toolkit/statistics.h"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>

namespace boxlod {
namespace {

const RenderMode render_modes[] = {RenderMode::untextured, RenderMode::normal, RenderMode::parallax, RenderMode::pom};
const LevelMode level_modes[] = {LevelMode::top_down,   LevelMode::bottom_up, LevelMode::bottom_up_siblings,
                                 LevelMode::box_volume, LevelMode::box_area,  LevelMode::box_diagonal,
                                 LevelMode::box_max_extent};
const BoxKind box_kinds[] = {BoxKind::scope, BoxKind::expanded, BoxKind::minimal};
const Interpolation interpolations[] = {Interpolation::linear, Interpolation::log, Interpolation::rank};

template <typename T, std::size_t N>
T next_of(const T (&values)[N], T current) {
    for (std::size_t i = 0; i < N; ++i)
        if (values[i] == current) return values[(i + 1) % N];
    return values[0];
}

float scene_radius(const ViewerState& s) { return std::max(model_bounds(*s.model).size().norm() / 2, 1e-6f); }

// Near and far follow the camera so the model is never clipped; so does the default light.
void camera_moved(ViewerState& s) {
    Camera& c = s.settings.camera;
    if (s.light_follows_camera) s.settings.light.position = light_for_camera(c).position;
    float distance = (c.position - model_bounds(*s.model).center()).norm();
    float radius = scene_radius(s);
    c.near_plane = std::max(distance - radius, std::max(distance * 1e-3f, radius * 1e-4f));
    c.far_plane = std::max(distance + radius, c.near_plane * 2);
}

void parameters_changed(ViewerState& s, const std::string& message) {
    s.needs_update = true;
    s.message = message;
}

}  // namespace

ViewerState make_viewer_state(const Model& model, const LodParameters& parameters, const RenderSettings& settings,
                              int width, int height, const Eigen::Vector3f& background) {
    ViewerState s;
    s.model = &model;
    s.parameters = parameters;
    s.settings = settings;
    s.width = width, s.height = height;
    s.background = background;
    s.original_drawable = make_drawable_model(model);
    return s;
}

std::string viewer_key_help() {
    return "W/A/S/D move, left-drag orbits, wheel: distance, C: next of the 26 camera positions,\n"
           "M: render mode, F: wireframe, X: coordinate cross, V: split view (LoD left, original right),\n"
           "+/-: current level, L: level mode, B: box kind, I: interpolation, U: update, Y: auto-update,\n"
           "T: show LoD texture, P: next page, [ ]: texture scale, Tab: statistics, G: light follows camera or stays,\n"
           "1/2 3/4 5/6 7/8: ambient, diffuse, specular, shininess down/up, H/N: get/set the sizing distance,\n"
           "F12: screenshot, F5: save parameters, F9: load parameters, F6: export the LoD, Q/Escape: quit";
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
        if (std::abs(turned.normalized().dot(camera.up)) < 0.995f) offset = turned;  // not over the pole
        else offset = yaw * offset;
        camera.position = camera.target + offset;
        camera_moved(s);
        return true;
    }
    if (e.kind == ViewerEvent::Kind::wheel) {
        camera.position = camera.target - forward * (distance * std::pow(0.9f, e.dy));
        camera_moved(s);
        return true;
    }
    const std::string& k = e.key;
    float step = std::max(distance, 1e-6f) * 0.05f;
    if (k == "w" || k == "s") {
        Eigen::Vector3f move = forward * (k == "w" ? step : -step);
        camera.position += move, camera.target += move;
    } else if (k == "a" || k == "d") {
        Eigen::Vector3f move = right * (k == "d" ? step : -step);
        camera.position += move, camera.target += move;
    } else if (k == "c") {
        std::vector<std::string> names = camera_position_names();
        s.camera_position = (s.camera_position + 1) % int(names.size());
        Bounds bounds = model_bounds(*s.model);
        camera = camera_at_position(*camera_direction(names[s.camera_position]), bounds.center(), distance,
                                    camera.fovy_degrees, scene_radius(s));
        s.message = "camera " + names[s.camera_position];
    } else if (k == "m") {
        s.settings.mode = next_of(render_modes, s.settings.mode);
        if (s.parameters.render_mode == RenderMode::untextured || s.settings.mode == RenderMode::untextured)
            parameters_changed(s, "");  // untextured LoDs are not baked
        s.parameters.render_mode = s.settings.mode;
        s.message = std::string("render mode ") + render_mode_name(s.settings.mode);
    } else if (k == "f") {
        s.settings.wireframe = !s.settings.wireframe;
    } else if (k == "x") {
        s.axes = !s.axes;
    } else if (k == "v") {
        s.split_view = !s.split_view;
    } else if (k == "+" || k == "=" || k == "keypad +") {
        ++s.parameters.current_level;
        parameters_changed(s, "level up");
    } else if (k == "-" || k == "keypad -") {
        s.parameters.current_level = std::max(0, s.parameters.current_level - 1);
        parameters_changed(s, "level down");
    } else if (k == "l") {
        s.parameters.level_mode = next_of(level_modes, s.parameters.level_mode);
        s.session.reset();
        parameters_changed(s, std::string("level mode ") + level_mode_name(s.parameters.level_mode));
    } else if (k == "b") {
        s.parameters.box_kind = next_of(box_kinds, s.parameters.box_kind);
        s.session.reset();
        parameters_changed(s, std::string("box kind ") + box_kind_name(s.parameters.box_kind));
    } else if (k == "i") {
        s.parameters.interpolation = next_of(interpolations, s.parameters.interpolation);
        s.session.reset();
        parameters_changed(s, std::string("interpolation ") + interpolation_name(s.parameters.interpolation));
    } else if (k == "u") {
        s.needs_update = s.update_now = true;
        s.message = "update";
    } else if (k == "y") {
        s.auto_update = !s.auto_update;
        s.message = s.auto_update ? "auto-update on" : "auto-update off";
    } else if (k == "t") {
        s.show_texture = !s.show_texture;
    } else if (k == "p") {
        s.texture_page = s.lod && !s.lod->atlas.pages.empty() ? (s.texture_page + 1) % int(s.lod->atlas.pages.size()) : 0;
    } else if (k == "[" || k == "]") {
        s.texture_scale *= k == "]" ? 2.0f : 0.5f;
    } else if (k == "tab") {
        s.show_statistics = !s.show_statistics;
    } else if (k == "h") {  // the manual's Get Distance: the camera's distance becomes the sizing distance
        s.parameters.distance = distance;
        s.session.reset();
        parameters_changed(s, "sizing distance " + format_number(distance));
    } else if (k == "n") {  // the manual's Set Distance: the camera moves to the sizing distance
        float wanted = s.parameters.distance > 0 ? s.parameters.distance : framing_distance(scene_radius(s), camera.fovy_degrees);
        camera.position = camera.target - forward * wanted;
        s.message = "distance " + format_number(wanted);
    } else if (k.size() == 1 && k[0] >= '1' && k[0] <= '8') {  // light options: 1/2 ambient, 3/4 diffuse, 5/6 specular, 7/8 shininess
        Light& light = s.settings.light;
        int option = (k[0] - '1') / 2;
        float factor = (k[0] - '1') % 2 ? 1.25f : 0.8f;
        float* values[4] = {&light.ambient, &light.diffuse, &light.specular, &light.shininess};
        if (option == 3 && light.shininess == 0) light.shininess = 32;  // start from the usual material value
        *values[option] *= factor;
        const char* names[4] = {"ambient", "diffuse", "specular", "shininess"};
        s.message = std::string(names[option]) + " " + format_number(*values[option]);
    } else if (k == "g") {
        s.light_follows_camera = !s.light_follows_camera;
        s.message = s.light_follows_camera ? "light follows the camera" : "light fixed";
    } else if (k == "f12") {
        s.screenshot = true;
        return false;
    } else if (k == "f5") {
        s.save_parameters = true;
        return false;
    } else if (k == "f9") {
        s.load_parameters = true;
        return false;
    } else if (k == "f6") {
        s.export_lod = true;
        return false;
    } else if (k == "q" || k == "escape") {
        s.quit = true;
        return false;
    } else {
        return false;
    }
    camera_moved(s);
    return true;
}

Frame render_view(ViewerState& s, int threads) {
    s.settings.threads = threads;
    bool rebuild = s.needs_update && (s.auto_update || s.update_now);
    s.update_now = false;
    if (rebuild && !s.model->is_lod) {
        s.lod.reset();
        s.lod_drawable.reset();
        if (s.parameters.current_level > 0) {
            if (!s.session) s.session = start_lod(*s.model, s.parameters, threads);
            s.parameters.current_level = std::min(s.parameters.current_level, s.session->levels.obtained_levels);
            s.lod = std::make_unique<Lod>(build_lod(*s.session, s.parameters.current_level, threads));
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
    view << "mode " << render_mode_name(s.settings.mode) << "  distance " << format_number((c.position - c.target).norm())
         << (s.settings.wireframe ? "  wireframe" : "") << (s.split_view ? "  split view" : "");
    lines.push_back(view.str());
    std::ostringstream lod;
    lod << "level " << s.parameters.current_level;
    if (s.session) lod << " of " << s.session->levels.obtained_levels;
    lod << "  " << level_mode_name(s.parameters.level_mode) << "  box " << box_kind_name(s.parameters.box_kind)
        << (s.auto_update ? "  auto-update" : "  (U: update)") << (s.needs_update ? "  *changed*" : "");
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
    auto fail = [&](const std::string& what) { throw_input_error(file, "line " + std::to_string(number), what); };
    if (word == "key") {
        if (!(in >> e.key)) fail("expected 'key NAME'");
        for (char& ch : e.key) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    } else if (word == "drag") {
        e.kind = ViewerEvent::Kind::drag;
        if (!(in >> e.dx >> e.dy)) fail("expected 'drag DX DY'");
    } else if (word == "wheel") {
        e.kind = ViewerEvent::Kind::wheel;
        if (!(in >> e.dy)) fail("expected 'wheel STEPS'");
    } else {
        fail("unknown event '" + word + "' (key, drag, wheel)");
    }
    std::string extra;
    if (in >> extra) fail("unexpected '" + extra + "'");
    return e;
}

}  // namespace boxlod
