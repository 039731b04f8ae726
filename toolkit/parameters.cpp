#include "toolkit/parameters.h"

#include "renderer/atomic_write.h"
#include "renderer/input_error.h"
#include "toolkit/key_value_lines.h"
#include "toolkit/key_values.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

namespace boxlod {
namespace {

std::string vector_text(const Eigen::Vector3f& v) {
    return format_number(v.x()) + " " + format_number(v.y()) + " " + format_number(v.z());
}

struct Parser {
    const std::string& file;
    int line;
    const std::string& key;

    [[noreturn]] void fail(const std::string& what) const {
        throw_input_error(file, "line " + std::to_string(line) + ": " + key, what);
    }
    float number(const std::string& text) const {
        float v = 0;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) fail("expected a number, got '" + text + "'");
        return v;
    }
    int integer(const std::string& text) const {
        int v = 0;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (error != std::errc() || end != text.data() + text.size()) fail("expected an integer, got '" + text + "'");
        return v;
    }
    bool boolean(const std::string& text) const {
        if (text != "true" && text != "false") fail("expected true or false, got '" + text + "'");
        return text == "true";
    }
    Eigen::Vector3f vector(const std::string& text) const {
        std::istringstream in(text);
        std::string a, b, c, extra;
        if (!(in >> a >> b >> c) || (in >> extra)) fail("expected three numbers 'x y z', got '" + text + "'");
        return {number(a), number(b), number(c)};
    }
};

}  // namespace

KeyValues parameter_entries(const LodParameters& p) {
    KeyValues out;
    auto line = [&](const std::string& key, const std::string& value) { out.push_back(text_entry(key, value)); };
    line("model", p.model);
    line("level_mode", level_mode_name(p.level_mode));
    line("wanted_levels", std::to_string(p.wanted_levels));
    line("current_level", std::to_string(p.current_level));
    line("box_kind", box_kind_name(p.box_kind));
    line("interpolation", interpolation_name(p.interpolation));
    line("keep_small_subtrees", p.keep_small_subtrees ? "true" : "false");
    line("keep_cheaper_subtrees", p.keep_cheaper_subtrees ? "true" : "false");
    line("crop_faces", p.crop_faces ? "true" : "false");
    line("fovy", format_number(p.fovy));
    line("distance", format_number(p.distance));
    line("resolution", format_number(p.resolution));
    line("min_texture_size", std::to_string(p.min_texture_size));
    line("max_texture_size", std::to_string(p.max_texture_size));
    line("render_mode", render_mode_name(p.render_mode));
    line("parallax_scale", format_number(p.parallax_scale));
    line("parallax_bias", format_number(p.parallax_bias));
    if (p.camera) {
        line("camera_position", vector_text(p.camera->position));
        line("camera_target", vector_text(p.camera->target));
        line("camera_up", vector_text(p.camera->up));
        line("camera_fovy", format_number(p.camera->fovy_degrees));
    }
    if (p.light) {
        line("light_position", vector_text(p.light->position));
        line("light_ambient", format_number(p.light->ambient));
        line("light_diffuse", format_number(p.light->diffuse));
        line("light_specular", format_number(p.light->specular));
        line("light_shininess", format_number(p.light->shininess));
    }
    return out;
}

std::string format_parameters(const LodParameters& p) {
    return "# boxlod LoD parameters\n" + format_key_values(parameter_entries(p));
}

LodParameters parse_parameters(const std::string& text, const std::string& file) {
    LodParameters p;
    Camera camera;
    Light light;
    bool has_camera = false, has_light = false;
    using Setter = std::function<void(const Parser&, const std::string&)>;
    auto camera_key = [&](auto apply) -> Setter { return [&, apply](const Parser& q, const std::string& v) { apply(q, v); has_camera = true; }; };
    auto light_key = [&](auto apply) -> Setter { return [&, apply](const Parser& q, const std::string& v) { apply(q, v); has_light = true; }; };
    const std::map<std::string, Setter> setters = {
        {"model", [&](const Parser&, const std::string& v) { p.model = v; }},
        {"level_mode", [&](const Parser& q, const std::string& v) { if (!parse_level_mode(v, p.level_mode)) q.fail("unknown level mode '" + v + "'"); }},
        {"wanted_levels", [&](const Parser& q, const std::string& v) { p.wanted_levels = q.integer(v); }},
        {"current_level", [&](const Parser& q, const std::string& v) { p.current_level = q.integer(v); }},
        {"box_kind", [&](const Parser& q, const std::string& v) { if (!parse_box_kind(v, p.box_kind)) q.fail("unknown box kind '" + v + "'"); }},
        {"interpolation", [&](const Parser& q, const std::string& v) { if (!parse_interpolation(v, p.interpolation)) q.fail("unknown interpolation '" + v + "'"); }},
        {"keep_small_subtrees", [&](const Parser& q, const std::string& v) { p.keep_small_subtrees = q.boolean(v); }},
        {"keep_cheaper_subtrees", [&](const Parser& q, const std::string& v) { p.keep_cheaper_subtrees = q.boolean(v); }},
        {"crop_faces", [&](const Parser& q, const std::string& v) { p.crop_faces = q.boolean(v); }},
        {"fovy", [&](const Parser& q, const std::string& v) { p.fovy = q.number(v); }},
        {"distance", [&](const Parser& q, const std::string& v) { p.distance = q.number(v); }},
        {"resolution", [&](const Parser& q, const std::string& v) { p.resolution = q.number(v); }},
        {"min_texture_size", [&](const Parser& q, const std::string& v) { p.min_texture_size = q.integer(v); }},
        {"max_texture_size", [&](const Parser& q, const std::string& v) { p.max_texture_size = q.integer(v); }},
        {"render_mode", [&](const Parser& q, const std::string& v) { if (!parse_render_mode(v, p.render_mode)) q.fail("unknown render mode '" + v + "'"); }},
        {"parallax_scale", [&](const Parser& q, const std::string& v) { p.parallax_scale = q.number(v); }},
        {"parallax_bias", [&](const Parser& q, const std::string& v) { p.parallax_bias = q.number(v); }},
        {"camera_position", camera_key([&](const Parser& q, const std::string& v) { camera.position = q.vector(v); })},
        {"camera_target", camera_key([&](const Parser& q, const std::string& v) { camera.target = q.vector(v); })},
        {"camera_up", camera_key([&](const Parser& q, const std::string& v) { camera.up = q.vector(v); })},
        {"camera_fovy", camera_key([&](const Parser& q, const std::string& v) { camera.fovy_degrees = q.number(v); })},
        {"light_position", light_key([&](const Parser& q, const std::string& v) { light.position = q.vector(v); })},
        {"light_ambient", light_key([&](const Parser& q, const std::string& v) { light.ambient = q.number(v); })},
        {"light_diffuse", light_key([&](const Parser& q, const std::string& v) { light.diffuse = q.number(v); })},
        {"light_specular", light_key([&](const Parser& q, const std::string& v) { light.specular = q.number(v); })},
        {"light_shininess", light_key([&](const Parser& q, const std::string& v) { light.shininess = q.number(v); })},
    };
    for (const KeyValueLine& line : parse_key_value_lines(text, file)) {
        auto setter = setters.find(line.key);
        Parser parser{file, line.line, line.key};
        if (setter == setters.end()) parser.fail("unknown key");
        if (line.value.empty()) parser.fail("missing value");
        setter->second(parser, line.value);
    }
    if (has_camera) p.camera = camera;
    if (has_light) p.light = light;
    validate_parameters(p, file);
    return p;
}

void validate_parameters(const LodParameters& p, const std::string& where) {
    auto fail = [&](const std::string& what) { throw_input_error(where, "", what); };
    auto power_of_two = [](int v) { return v > 0 && (v & (v - 1)) == 0; };
    if (p.wanted_levels < 1) fail("wanted_levels must be at least 1");
    if (p.current_level < 0) fail("current_level must be 0 or more");
    if (!(p.fovy > 0 && p.fovy < 180)) fail("fovy must be in (0, 180) degrees");
    if (p.distance < 0) fail("distance must be positive (or 0 for the framing distance)");
    if (!(p.resolution >= 1)) fail("resolution must be at least 1 pixel");
    if (!power_of_two(p.min_texture_size) || !power_of_two(p.max_texture_size) || p.min_texture_size > p.max_texture_size ||
        p.max_texture_size < 16 || p.max_texture_size > 16384)
        fail("min_texture_size and max_texture_size must be powers of two with 16 <= max <= 16384 and min <= max");
}

LodParameters load_parameters(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw_input_error(path, "", "cannot open parameter file");
    std::stringstream text;
    text << in.rdbuf();
    LodParameters p = parse_parameters(text.str(), path);
    // The model is named relative to the parameter file.
    if (!p.model.empty() && std::filesystem::path(p.model).is_relative())
        p.model = (std::filesystem::path(path).parent_path() / p.model).lexically_normal().string();
    return p;
}

void save_parameters(const std::string& path, const LodParameters& parameters) {
    write_text_atomically(path, format_parameters(parameters));
}

}  // namespace boxlod
