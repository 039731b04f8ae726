#include "toolkit/lod/parameter_file.h"

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
    for (const ParameterDeclaration& d : lod_parameter_declarations())
        if (d.written_at_default || d.format(p) != d.format(LodParameters{})) line(d.key, d.format(p));
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
    // The view's keys; the LoD parameters are declared in lod_parameters.cpp.
    const std::map<std::string, Setter> setters = {
        {"model", [&](const Parser&, const std::string& v) { p.model = v; }},
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
        Parser parser{file, line.line, line.key};
        if (line.value.empty()) parser.fail("missing value");
        if (const ParameterDeclaration* declared = find_lod_parameter(line.key)) {
            if (std::string problem = declared->parse(line.value, p); !problem.empty()) parser.fail(problem);
            continue;
        }
        auto setter = setters.find(line.key);
        if (setter == setters.end()) parser.fail("unknown key");
        setter->second(parser, line.value);
    }
    if (has_camera) p.camera = camera;
    if (has_light) p.light = light;
    validate_parameters(p, file);
    return p;
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
