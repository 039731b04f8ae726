#include "toolkit/lod/parameter_file.h"

#include "base/atomic_write.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/key_value_lines.h"
#include "base/key_values.h"
#include "base/number_text.h"

#include <cfloat>
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
        const auto v = number_within<float>(text, range);
        if (!v) fail(number_problem<float>(text, range));
        return *v;
    }
    Eigen::Vector3f vector(const std::string& text,
                           const NumberRange& range = parameter_range::position) const {
        std::istringstream in(text);
        std::string a, b, c, extra;
        if (!(in >> a >> b >> c) || (in >> extra)) fail("expected three numbers 'x y z', got '" + text + "'");
        return {number(a, range), number(b, range), number(c, range)};
    }
};

using ViewSetter = std::function<void(const Parser&, const std::string&)>;

// The keys of the view a parameter file may state; the LoD parameters are declared in lod_parameters.cpp.
std::map<std::string, ViewSetter> view_keys(Camera& camera, Light& light) {
    namespace r = parameter_range;
    using P = const Parser&;
    using V = const std::string&;
    return {
        {"camera_position", [&](P q, V v) { camera.position = q.vector(v); }},
        {"camera_target", [&](P q, V v) { camera.target = q.vector(v); }},
        {"camera_up", [&](P q, V v) { camera.up = q.vector(v); }},
        {"camera_fovy", [&](P q, V v) { camera.fovy_degrees = q.number(v, r::fovy); }},
        {"light_position", [&](P q, V v) { light.position = q.vector(v); }},
        {"light_ambient", [&](P q, V v) { light.ambient = q.number(v, light_intensity_range); }},
        {"light_diffuse", [&](P q, V v) { light.diffuse = q.number(v, light_intensity_range); }},
        {"light_specular", [&](P q, V v) { light.specular = q.number(v, light_intensity_range); }},
        {"light_shininess", [&](P q, V v) { light.shininess = q.number(v, shininess_range); }},
    };
}

}  // namespace

KeyValues parameter_entries(const LodParameters& p) {
    KeyValues out;
    auto line = [&](const std::string& key, const std::string& value) {
        out.push_back(text_entry(key, value));
    };
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
    bool has_camera = false, has_light = false;  // a view given in part takes the rest from the defaults
    for (const ParameterDeclaration& d : lod_parameter_declarations())
        if (!d.absent_from_file.empty()) d.parse(d.absent_from_file, p);  // docs/design.md: Parameter file
    const std::map<std::string, ViewSetter> setters = view_keys(camera, light);
    for (const KeyValueLine& line : parse_key_value_lines(text, file)) {
        Parser parser{file, line.line, line.key};
        if (line.value.empty()) parser.fail("missing value");
        if (const ParameterDeclaration* declared = find_lod_parameter(line.key)) {
            if (std::string problem = declared->parse(line.value, p); !problem.empty()) parser.fail(problem);
            continue;
        }
        if (line.key == "model") {
            p.model = line.value;
            continue;
        }
        auto setter = setters.find(line.key);
        if (setter == setters.end()) parser.fail("unknown key");
        setter->second(parser, line.value);
        (line.key.starts_with("camera_") ? has_camera : has_light) = true;
    }
    if (has_camera) p.camera = camera;
    if (has_light) p.light = light;
    validate_parameters(p, file);
    return p;
}

LodParameters load_parameters(const std::string& path) {
    LodParameters p = parse_parameters(read_input_file(path, "parameter file"), path);
    // The file names a relative model relative to itself; in memory it is
    // relative to the working folder again, so saving it elsewhere keeps it
    // relative (save_parameters).
    namespace fs = std::filesystem;
    if (!p.model.empty() && fs::path(p.model).is_relative()) {
        fs::path model = (fs::path(path).parent_path() / p.model).lexically_normal();
        std::error_code error;
        const fs::path working = fs::current_path(error);
        if (model.is_absolute() && !error) model = model.lexically_proximate(working);
        p.model = model.string();
    }
    return p;
}

void save_parameters(const std::string& path, const LodParameters& parameters) {
    namespace fs = std::filesystem;
    // An absolute model path is kept as the user gave it; a relative one (to
    // the working folder) is written relative to the file, as it reads back,
    // so the two can move together.
    LodParameters saved = parameters;
    if (fs::path(saved.model).is_relative() && !saved.model.empty()) {
        std::error_code folder_error, model_error;
        const fs::path folder = fs::absolute(path, folder_error).parent_path().lexically_normal();
        const fs::path model = fs::absolute(saved.model, model_error).lexically_normal();
        const fs::path relative = model.lexically_relative(folder);
        if (!folder_error && !model_error && !relative.empty()) saved.model = relative.string();
    }
    write_text_atomically(path, format_parameters(saved));
}

}  // namespace boxlod
