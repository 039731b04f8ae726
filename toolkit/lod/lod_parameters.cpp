#include "toolkit/lod/lod_parameters.h"

#include "base/enum_table.h"
#include "base/key_values.h"
#include "base/number_text.h"

#include <cmath>
#include <utility>
#include <vector>

namespace boxlod {
namespace {

ParameterDeclaration named(const char* key, const char* option, const char* value_name, std::string help) {
    ParameterDeclaration d;
    d.key = key;
    d.option = option;
    d.value_name = value_name;
    d.help = std::move(help);
    return d;
}

// Declarations by kind; the member pointer is the parameter's field.
template <typename Number>
ParameterDeclaration number_parameter(const char* key, const char* option, const char* value_name,
                                      const char* help, Number LodParameters::*field, NumberRange range,
                                      bool power_of_two = false) {
    ParameterDeclaration d = named(key, option, value_name, help);
    d.range = range;
    d.power_of_two = power_of_two;
    d.format = [field](const LodParameters& p) {
        if constexpr (std::is_integral_v<Number>)
            return std::to_string(p.*field);
        else
            return format_number(p.*field);
    };
    d.parse = [field, range, power_of_two](const std::string& text, LodParameters& p) -> std::string {
        const auto value = number_within<Number>(text, range);
        if (!value) return number_problem<Number>(text, range);
        if (power_of_two) {
            auto whole = static_cast<long long>(*value);
            if (whole <= 0 || (whole & (whole - 1)) != 0)
                return "expected a power of two in " + range_text(range) + ", got '" + text + "'";
        }
        p.*field = *value;
        return "";
    };
    d.number = [field](const LodParameters& p) { return double(p.*field); };
    return d;
}

ParameterDeclaration yes_no_parameter(const char* key, const char* option, const char* help,
                                      bool LodParameters::*field) {
    ParameterDeclaration d = named(key, option, "", help);
    d.format = [field](const LodParameters& p) { return std::string(p.*field ? "true" : "false"); };
    d.parse = [field](const std::string& text, LodParameters& p) -> std::string {
        if (text != "true" && text != "false") return "expected true or false, got '" + text + "'";
        p.*field = text == "true";
        return "";
    };
    return d;
}

template <typename Enum>
ParameterDeclaration enum_parameter(const char* key, const char* option, const char* value_name,
                                    const std::string& help, Enum LodParameters::*field,
                                    std::span<const EnumEntry<Enum>> table) {
    ParameterDeclaration d = named(key, option, value_name, help + enum_names(table, ", ", " or "));
    d.sweep_key = false;  // a sweep lists the values it varies (level_modes = ..., render_modes = ...)
    d.format = [field, table](const LodParameters& p) { return std::string(enum_name(table, p.*field)); };
    d.parse = [field, table](const std::string& text, LodParameters& p) -> std::string {
        if (!parse_enum(table, text, p.*field))
            return "unknown value '" + text + "' (" + enum_names(table) + ")";
        return "";
    };
    return d;
}

ParameterDeclaration budgets_parameter() {
    ParameterDeclaration d = named(
        "budgets", "budgets", "B1,...,BN",
        "beyond the manual, for level modes error-greedy and hybrid: one level per byte budget, level c the "
        "best cut whose bytes (mesh + GPU-compressed textures) stay within the c-th, descending: fractions "
        "of the original's bytes (0.5,0.25,0.1,0.05) or sizes (2MB,500kB); none: wanted_levels levels at "
        "budgets geometric from the coarsest cut to the original (docs/design.md: Levels by byte budget)");
    d.format = [](const LodParameters& p) { return format_budgets(p.budgets); };
    d.parse = [](const std::string& text, LodParameters& p) { return parse_budgets(text, p.budgets); };
    return d;
}

std::string format_level_distances(const LevelDistances& distances) {
    if (distances.rule == LevelDistances::Rule::doubling) return "auto";
    if (distances.rule == LevelDistances::Rule::same) return "same";
    std::string text;
    for (float d : distances.listed) {
        if (!text.empty()) text += ',';
        text += format_number(d);
    }
    return text;
}

// auto, same, or distances that ascend strictly: two levels sized for one
// distance would draw the same (docs/design.md: Files).
std::string parse_level_distances(const std::string& text, LevelDistances& distances) {
    LevelDistances parsed;
    if (text == "auto" || text == "same") {
        parsed.rule = text == "auto" ? LevelDistances::Rule::doubling : LevelDistances::Rule::same;
        distances = parsed;
        return "";
    }
    parsed.rule = LevelDistances::Rule::listed;
    for (const std::string& item : comma_list(text)) {
        const auto d = number_within<double>(item, parameter_range::distance);
        if (!d || *d < parameter_range::min_positive_distance)
            return "'" + item + "' is not a distance in [" +
                   format_number(parameter_range::min_positive_distance) + ", " +
                   format_number(parameter_range::distance.max) + "] m (or auto, or same)";
        if (!parsed.listed.empty() && !(float(*d) > parsed.listed.back()))
            return item + " comes after " + format_number(parsed.listed.back()) +
                   ": the distances must ascend, one per level 1..N";
        parsed.listed.push_back(float(*d));
    }
    distances = parsed;
    return "";
}

ParameterDeclaration level_distances_parameter() {
    ParameterDeclaration d =
        named("level_distances", "level-distances", "auto|same|D1,...,DN",
              "where a chain's level c >= 1 is sized: auto, the distance x 2^(c-1) (with budgets at most x "
              "B_1/B_c), so each level is as "
              "sharp as the screen where it is used; same, every level at the distance (--manual); or one "
              "distance per level 1..N, ascending (docs/cost.md: Switching levels)");
    d.sweep_key = false;  // a sweep sizes by its own `sizing` rule
    d.format = [](const LodParameters& p) { return format_level_distances(p.level_distances); };
    d.parse = [](const std::string& text, LodParameters& p) {
        return parse_level_distances(text, p.level_distances);
    };
    return d;
}

// Which geometry of a CityJSON model is read: the model's, as the file names
// its LoDs, so a parameter file states it only for such models.
ParameterDeclaration city_lod_parameter() {
    ParameterDeclaration d = named("city_lod", "city-lod", "finest|L",
                                   "CityJSON models: the LoD read, as the file names it (1.2, 2.2; objects "
                                   "without it are left out), or each object's finest");
    d.sweep_key = false;
    d.written_at_default = false;
    d.format = [](const LodParameters& p) { return p.city_lod.empty() ? std::string("finest") : p.city_lod; };
    d.parse = [](const std::string& text, LodParameters& p) -> std::string {
        const std::size_t dot = text.find('.');
        if (text != "finest" &&
            (text.empty() || text.size() > 8 || text.find_first_not_of("0123456789.") != std::string::npos ||
             dot == 0 || dot + 1 == text.size() || text.find('.', dot + 1) != std::string::npos))
            return "'" + text + "' is not a LoD (finest, or as the file names it: 1.2, 2.2)";
        p.city_lod = text == "finest" ? "" : text;
        return "";
    };
    return d;
}

ParameterDeclaration not_in_sweeps(ParameterDeclaration declaration) {
    declaration.sweep_key = false;
    return declaration;
}

// On by default: at equal quality by distance, hybrid levels with baked
// proxies are cheaper on far levels of every kind of building measured
// (docs/cost.md: Baked proxies).
ParameterDeclaration baked_proxies_parameter() {
    ParameterDeclaration d =
        yes_no_parameter("baked_proxies", "no-baked-proxies",
                         "level mode hybrid: do not offer each sub-tree's baked proxy, its geometry "
                         "simplified as one mesh and "
                         "drawn with its box's baked faces (docs/design.md: The hybrid level mode)",
                         &LodParameters::baked_proxies);
    d.absent_from_file = "false";  // files written while off by default named it only where on
    return d;
}

std::vector<ParameterDeclaration> make_declarations() {
    namespace r = parameter_range;
    using P = LodParameters;
    return {
        city_lod_parameter(),
        enum_parameter("level_mode", "level-mode", "M", "how nodes get their level values: ", &P::level_mode,
                       level_modes()),
        number_parameter("wanted_levels", "wanted-levels", "N", "wanted number of levels for the box modes",
                         &P::wanted_levels, r::wanted_levels),
        budgets_parameter(),
        // A sweep measures every level it lists (`levels = ...`).
        not_in_sweeps(number_parameter("current_level", "level", "C",
                                       "current level, 0 (original) .. obtained levels (one box)",
                                       &P::current_level, r::current_level)),
        enum_parameter("box_kind", "box", "KIND", "boxes for the box modes: ", &P::box_kind, box_kinds()),
        enum_parameter("interpolation", "interpolation", "I",
                       "how box modes map box values to levels: ", &P::interpolation, interpolations()),
        yes_no_parameter("keep_small_subtrees", "keep-small-subtrees",
                         "beyond the manual: a sub-tree of at most 6 faces keeps its geometry instead of a "
                         "6-face box, so no level draws more faces than the original",
                         &P::keep_small_subtrees),
        yes_no_parameter("keep_cheaper_subtrees", "box-cheaper-subtrees",
                         "as the manual, box every sub-tree, also those whose mesh costs fewer bytes than "
                         "their textured box would (by default such a node keeps its geometry, so no box "
                         "costs more than what it replaces)",
                         &P::keep_cheaper_subtrees),
        yes_no_parameter("crop_faces", "no-crop",
                         "keep every baked face whole instead of cropping it to its covered texels (and "
                         "dropping faces with none)",
                         &P::crop_faces),
        number_parameter(
            "flat_faces", "flat-faces", "N",
            "beyond the manual: a face whose (cropped) texels are at most N on its longer side and at least "
            "half covered is drawn in one colour, its covered texels' mean, from a shared 4x4 swatch without "
            "gutters, in levels whose pages it makes smaller (docs/design.md: Atlas); 0: off",
            &P::flat_faces, r::flat_faces),
        baked_proxies_parameter(),
        number_parameter("fovy", "fovy", "DEG", "texture sizing: vertical field of view in degrees", &P::fovy,
                         r::fovy),
        // A sweep sizes for its own `distances` (multiples of the framing distance).
        not_in_sweeps(number_parameter(
            "distance", "distance", "D",
            "texture sizing: camera distance in metres, 0: the distance that frames the model", &P::distance,
            r::distance)),
        level_distances_parameter(),
        number_parameter("resolution", "resolution", "R", "texture sizing: screen height in pixels",
                         &P::resolution, r::resolution),
        number_parameter("min_texture_size", "min-texture-size", "S",
                         "smallest LoD texture page side, a power of two", &P::min_texture_size,
                         r::texture_size, true),
        number_parameter("max_texture_size", "max-texture-size", "S",
                         "largest LoD texture page side, a power of two", &P::max_texture_size,
                         r::texture_size, true),
        enum_parameter("render_mode", "render-mode", "M",
                       "how the LoD is drawn (untextured LoDs are not baked): ", &P::render_mode,
                       render_modes()),
        number_parameter("parallax_scale", "parallax-scale", "S",
                         "parallax height scale, in texture units, for height maps that state no depth (LoD "
                         "pages state theirs, in metres)",
                         &P::parallax_scale, r::parallax),
        number_parameter("parallax_bias", "parallax-bias", "B",
                         "parallax height bias, in texture units, as the scale", &P::parallax_bias,
                         r::parallax),
    };
}

}  // namespace

std::string ParameterDeclaration::help_text() const {
    if (is_flag()) return help;
    return help + " (default " + format(LodParameters{}) + ")";
}

std::span<const ParameterDeclaration> lod_parameter_declarations() {
    static const std::vector<ParameterDeclaration> declarations = make_declarations();
    return declarations;
}

const ParameterDeclaration* find_lod_parameter(const std::string& key) {
    for (const ParameterDeclaration& d : lod_parameter_declarations())
        if (d.key == key) return &d;
    return nullptr;
}

void set_manual(LodParameters& p) {
    p.keep_small_subtrees = false;
    p.keep_cheaper_subtrees = false;
    p.min_texture_size = 256;
    p.flat_faces = 0;
    p.level_distances.rule = LevelDistances::Rule::same;
}

int asked_levels(const LodParameters& p) {
    return p.budgets.empty() || !orders_by_bytes(p.level_mode) ? p.wanted_levels : int(p.budgets.size());
}

void validate_parameters(const LodParameters& p, const std::string& where) {
    auto fail = [&](const std::string& what) { throw_input_error(where, "", what); };
    // Named as the user wrote it: an option on the command line, a key in a file.
    auto spelled = [&](const std::string& key) {
        const ParameterDeclaration* d = where == "command line" ? find_lod_parameter(key) : nullptr;
        return d && !d->option.empty() ? "--" + d->option : key;
    };
    auto check = [&](const std::string& key, double value, const NumberRange& range) {
        if (!range.contains(value))
            fail(spelled(key) + ": " + out_of_range_message(range, format_number(value)));
    };
    for (const ParameterDeclaration& d : lod_parameter_declarations())
        if (d.range) check(d.key, d.number(p), *d.range);
    namespace r = parameter_range;
    if (p.distance > 0 && p.distance < r::min_positive_distance)
        fail(spelled("distance") + ": 0 (the framing distance) or at least 0.001 m");
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
    if (!power_of_two(p.min_texture_size) || !power_of_two(p.max_texture_size) ||
        p.min_texture_size > p.max_texture_size || p.max_texture_size < 16)
        fail("min_texture_size and max_texture_size must be powers of two with 16 <= max and min <= max");
}

RenderSettings drawing_settings(const Camera& camera, RenderMode mode, const LodParameters& parameters,
                                int threads) {
    RenderSettings settings;
    settings.camera = camera;
    settings.mode = mode;
    settings.parallax_scale = parameters.parallax_scale;
    settings.parallax_bias = parameters.parallax_bias;
    settings.light = light_for_camera(camera);
    settings.threads = threads;
    return settings;
}

}  // namespace boxlod
