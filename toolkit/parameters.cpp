#include "toolkit/parameters.h"

#include "base/atomic_write.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/key_value_lines.h"
#include "base/key_values.h"

#include <cfloat>
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
    float number(const std::string& text, const NumberRange& range = {-FLT_MAX, FLT_MAX}) const {
        float v = 0;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (error != std::errc() || end != text.data() + text.size() || !range.contains(v)) fail(out_of_range_message(range, text));
        return v;
    }
    int integer(const std::string& text, const NumberRange& range) const {
        int v = 0;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (error != std::errc() || end != text.data() + text.size()) fail("expected an integer, got '" + text + "'");
        if (!range.contains(v)) fail(out_of_range_message(range, text));
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
    namespace r = parameter_range;
    using Setter = std::function<void(const Parser&, const std::string&)>;
    auto camera_key = [&](auto apply) -> Setter { return [&, apply](const Parser& q, const std::string& v) { apply(q, v); has_camera = true; }; };
    auto light_key = [&](auto apply) -> Setter { return [&, apply](const Parser& q, const std::string& v) { apply(q, v); has_light = true; }; };
    const std::map<std::string, Setter> setters = {
        {"model", [&](const Parser&, const std::string& v) { p.model = v; }},
        {"level_mode", [&](const Parser& q, const std::string& v) { if (!parse_level_mode(v, p.level_mode)) q.fail("unknown level mode '" + v + "'"); }},
        {"wanted_levels", [&](const Parser& q, const std::string& v) { p.wanted_levels = q.integer(v, r::wanted_levels); }},
        {"current_level", [&](const Parser& q, const std::string& v) { p.current_level = q.integer(v, r::current_level); }},
        {"box_kind", [&](const Parser& q, const std::string& v) { if (!parse_box_kind(v, p.box_kind)) q.fail("unknown box kind '" + v + "'"); }},
        {"interpolation", [&](const Parser& q, const std::string& v) { if (!parse_interpolation(v, p.interpolation)) q.fail("unknown interpolation '" + v + "'"); }},
        {"keep_small_subtrees", [&](const Parser& q, const std::string& v) { p.keep_small_subtrees = q.boolean(v); }},
        {"keep_cheaper_subtrees", [&](const Parser& q, const std::string& v) { p.keep_cheaper_subtrees = q.boolean(v); }},
        {"crop_faces", [&](const Parser& q, const std::string& v) { p.crop_faces = q.boolean(v); }},
        {"fovy", [&](const Parser& q, const std::string& v) { p.fovy = q.number(v, r::fovy); }},
        {"distance", [&](const Parser& q, const std::string& v) { p.distance = q.number(v, r::distance); }},
        {"resolution", [&](const Parser& q, const std::string& v) { p.resolution = q.number(v, r::resolution); }},
        {"min_texture_size", [&](const Parser& q, const std::string& v) { p.min_texture_size = q.integer(v, r::texture_size); }},
        {"max_texture_size", [&](const Parser& q, const std::string& v) { p.max_texture_size = q.integer(v, r::texture_size); }},
        {"render_mode", [&](const Parser& q, const std::string& v) { if (!parse_render_mode(v, p.render_mode)) q.fail("unknown render mode '" + v + "'"); }},
        {"parallax_scale", [&](const Parser& q, const std::string& v) { p.parallax_scale = q.number(v, r::parallax); }},
        {"parallax_bias", [&](const Parser& q, const std::string& v) { p.parallax_bias = q.number(v, r::parallax); }},
        {"camera_position", camera_key([&](const Parser& q, const std::string& v) { camera.position = q.vector(v); })},
        {"camera_target", camera_key([&](const Parser& q, const std::string& v) { camera.target = q.vector(v); })},
        {"camera_up", camera_key([&](const Parser& q, const std::string& v) { camera.up = q.vector(v); })},
        {"camera_fovy", camera_key([&](const Parser& q, const std::string& v) { camera.fovy_degrees = q.number(v, r::fovy); })},
        {"light_position", light_key([&](const Parser& q, const std::string& v) { light.position = q.vector(v); })},
        {"light_ambient", light_key([&](const Parser& q, const std::string& v) { light.ambient = q.number(v, light_intensity_range); })},
        {"light_diffuse", light_key([&](const Parser& q, const std::string& v) { light.diffuse = q.number(v, light_intensity_range); })},
        {"light_specular", light_key([&](const Parser& q, const std::string& v) { light.specular = q.number(v, light_intensity_range); })},
        {"light_shininess", light_key([&](const Parser& q, const std::string& v) { light.shininess = q.number(v, shininess_range); })},
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
    auto check = [&](const char* key, double value, const NumberRange& range) {
        if (!range.contains(value)) fail(std::string(key) + ": " + out_of_range_message(range, format_number(value)));
    };
    namespace r = parameter_range;
    check("wanted_levels", p.wanted_levels, r::wanted_levels);
    check("current_level", p.current_level, r::current_level);
    check("fovy", p.fovy, r::fovy);
    check("distance", p.distance, r::distance);
    if (p.distance > 0 && p.distance < r::min_positive_distance) fail("distance: 0 (the framing distance) or at least 0.001 m");
    check("resolution", p.resolution, r::resolution);
    check("min_texture_size", p.min_texture_size, r::texture_size);
    check("max_texture_size", p.max_texture_size, r::texture_size);
    check("parallax_scale", p.parallax_scale, r::parallax);
    check("parallax_bias", p.parallax_bias, r::parallax);
    if (p.camera) {
        check("camera_fovy", p.camera->fovy_degrees, r::fovy);
        if (std::string problem = camera_problem(*p.camera); !problem.empty()) fail(problem);
    }
    if (p.light) {
        if (!p.light->position.allFinite()) fail("light_position is not finite");
        check("light_ambient", p.light->ambient, light_intensity_range);
        check("light_diffuse", p.light->diffuse, light_intensity_range);
        check("light_specular", p.light->specular, light_intensity_range);
        check("light_shininess", p.light->shininess, shininess_range);
    }
    auto power_of_two = [](int v) { return v > 0 && (v & (v - 1)) == 0; };
    if (!power_of_two(p.min_texture_size) || !power_of_two(p.max_texture_size) || p.min_texture_size > p.max_texture_size ||
        p.max_texture_size < 16)
        fail("min_texture_size and max_texture_size must be powers of two with 16 <= max and min <= max");
}

LodParameters load_parameters(const std::string& path) {
    LodParameters p = parse_parameters(read_input_file(path, "parameter file"), path);
    // The model is named relative to the parameter file.
    if (!p.model.empty() && std::filesystem::path(p.model).is_relative())
        p.model = (std::filesystem::path(path).parent_path() / p.model).lexically_normal().string();
    return p;
}

void save_parameters(const std::string& path, const LodParameters& parameters) {
    write_text_atomically(path, format_parameters(parameters));
}

}  // namespace boxlod
