// The parameter file (docs/design.md: Parameter file; the manual's Loading and
// Saving Files): plain text, one `key = value` per line, `#` comments. It
// holds the model file, every LoD parameter, the camera and the light.
#pragma once
#include "base/input_error.h"
#include "base/key_values.h"
#include "renderer/renderer.h"
#include "toolkit/boxes.h"
#include "toolkit/level_modes.h"

#include <optional>
#include <string>

namespace boxlod {

struct LodParameters {
    std::string model;  // the model file (relative paths are relative to the parameter file)
    LevelMode level_mode = LevelMode::top_down;
    int wanted_levels = 8;
    int current_level = 1;
    BoxKind box_kind = BoxKind::expanded;
    Interpolation interpolation = Interpolation::linear;
    bool keep_small_subtrees = false;    // beyond the manual: no box for a sub-tree of <= 6 faces (kept_subtrees.h)
    bool keep_cheaper_subtrees = false;  // beyond the manual: no box costing more bytes than its sub-tree's mesh
    bool crop_faces = true;  // a baked face keeps only the rectangle of its covered texels; none covered: no quad
    // Texture sizing: the virtual camera whose pixels the texels match.
    float fovy = 45;
    float distance = 0;  // 0: the distance that frames the model
    float resolution = 1080;
    int min_texture_size = 256, max_texture_size = 4096;
    RenderMode render_mode = RenderMode::normal;
    float parallax_scale = 0.04f, parallax_bias = -0.02f;
    // The view for the preview; unset: camera +X+Y+Z at the sizing distance.
    std::optional<Camera> camera;
    std::optional<Light> light;
};

// The accepted values of the numeric parameters, declared once: the command
// line, parameter files and sweep configs all check against these.
namespace parameter_range {
constexpr NumberRange wanted_levels{1, 64};
constexpr NumberRange current_level{0, 10000};  // and at most the levels obtained, checked when building
constexpr NumberRange fovy{0.1, 179};
constexpr NumberRange distance{0, 1e6};         // metres; 0: the distance that frames the model
constexpr double min_positive_distance = 1e-3;  // a sizing camera nearer than 1 mm sizes nothing sensible
constexpr NumberRange resolution{1, 16384};     // pixels
constexpr NumberRange texture_size{1, 16384};   // and a power of two
constexpr NumberRange parallax{-1, 1};          // scale and bias, in texture units
}  // namespace parameter_range

// Every key in file order, numbers printed so they read back exactly.
KeyValues parameter_entries(const LodParameters& parameters);
std::string format_parameters(const LodParameters& parameters);
// `file` names the source in errors: "file:line: key: what is wrong".
LodParameters parse_parameters(const std::string& text, const std::string& file);
LodParameters load_parameters(const std::string& path);
void save_parameters(const std::string& path, const LodParameters& parameters);  // atomic

// Checks ranges (levels >= 1, sizes powers of two, min <= max, ...); throws InputError naming `where`.
void validate_parameters(const LodParameters& parameters, const std::string& where);

}  // namespace boxlod
