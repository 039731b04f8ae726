// The LoD parameters (docs/design.md: Parameter file), each declared once:
// its key in parameter files and sweep configs, its command-line option, its
// default (from LodParameters{}), range and help. Parsing, validation, --help,
// the parameter file and the sweep's keys all read the declarations.
#pragma once
#include "base/input_error.h"
#include "renderer/renderer.h"
#include "toolkit/lod/cut/level_budgets.h"
#include "toolkit/lod/cut/level_modes.h"
#include "toolkit/lod/pages/boxes.h"

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace boxlod {

// Where levels 1..N of a chain are sized (toolkit/lod/chain/chain.h): `auto`
// doubles the distance per level, `same` sizes every level at the distance
// (the manual's program), or one listed distance per level.
struct LevelDistances {
    enum class Rule { doubling, same, listed } rule = Rule::doubling;
    std::vector<float> listed;  // rule listed: ascending, one per level 1..N
};

struct LodParameters {
    std::string model;     // the model file (relative: to the working folder; parameter_file.h)
    std::string city_lod;  // a CityJSON model's LoD read ("": each object's finest;
                           // toolkit/formats/cityjson_import.h)
    LevelMode level_mode = LevelMode::top_down;
    int wanted_levels = 8;
    std::vector<ByteBudget>
        budgets;  // beyond the manual: one level per budget (level_budgets.h); empty: wanted_levels
    int current_level = 1;
    BoxKind box_kind = BoxKind::expanded;
    Interpolation interpolation = Interpolation::linear;
    bool keep_small_subtrees =
        false;  // beyond the manual: no box for a sub-tree of <= 6 faces (kept_subtrees.h)
    // The defaults are the chain that pays its way (docs/cost.md); set_manual gives the manual's program.
    bool keep_cheaper_subtrees =
        true;  // beyond the manual: no box costing more bytes than its sub-tree's mesh
    bool crop_faces =
        true;  // a baked face keeps only the rectangle of its covered texels; none covered: no quad
    int flat_faces =
        8;  // beyond the manual: faces up to this many texels drawn in one colour from a swatch; 0: off
    bool baked_proxies =
        true;  // beyond the manual, level mode hybrid: also baked proxies (hybrid.h, baked_proxy.h)
    // Texture sizing: the virtual camera whose pixels the texels match.
    float fovy = 45;
    float distance = 0;  // 0: the distance that frames the model; a chain's level 1
    LevelDistances level_distances;
    float resolution = 1080;
    int min_texture_size = 16, max_texture_size = 4096;
    RenderMode render_mode = RenderMode::normal;
    float parallax_scale = 0.04f, parallax_bias = -0.02f;
    // The view for the preview; unset: camera +X+Y+Z at the sizing distance.
    std::optional<Camera> camera;
    std::optional<Light> light;
};

// The ranges of the numeric parameters (their declarations and the few
// commands that take one of them under another name read these).
namespace parameter_range {
constexpr NumberRange wanted_levels{1, 64};
constexpr NumberRange current_level{0, 10000};  // and at most the levels obtained, checked when building
constexpr NumberRange fovy{0.1, 179};
// Metres, or the model's units (an FBX in centimetres: 100 per metre); 0: the
// distance that frames the model. As far as a level's may lie: auto doubles
// the distance per level, to 2^9 times the framing distance in a 10-level chain.
constexpr NumberRange distance{0, 1e12};
constexpr double min_positive_distance = 1e-3;  // a sizing camera nearer than 1 mm sizes nothing sensible
constexpr NumberRange resolution{1, 16384};     // pixels
constexpr NumberRange texture_size{1, 16384};   // and a power of two
constexpr NumberRange parallax{-1, 1};    // scale and bias, in texture units (docs/design.md: Rendering)
constexpr NumberRange flat_faces{0, 64};  // texels on a face's longer side; 0: off
// A camera's or light's coordinates, in the model's units: as a model's (toolkit/model/model.h), and
// squared distances between them finite in float.
constexpr NumberRange position = coordinate_range;
}  // namespace parameter_range

struct ParameterDeclaration {
    std::string key;     // parameter files and sweep configs: "wanted_levels"
    std::string option;  // the command line: "wanted-levels"; a yes/no parameter's option is a flag that sets
                         // the opposite of its default
    std::string value_name;            // "N"; empty for yes/no
    std::string help;                  // without the default, which help_text() adds
    std::optional<NumberRange> range;  // numbers only
    bool power_of_two = false;         // numbers only
    bool sweep_key =
        true;  // a sweep config sets it with `key = value`; false: the sweep varies it under a key of its own
    bool written_at_default =
        true;  // false: a parameter file names it only where it differs from the default
    // Set: what a parameter file without the key means, where that is not today's default (files written
    // before the default changed still build their level).
    std::string absent_from_file;
    std::function<std::string(const LodParameters&)> format;  // reads back exactly through parse
    // Reads `text` into `parameters`; returns what is wrong ("" when nothing is).
    std::function<std::string(const std::string& text, LodParameters& parameters)> parse;
    std::function<double(const LodParameters&)> number;  // numbers only: the value, for range checks

    bool is_flag() const { return value_name.empty(); }
    std::string help_text() const;  // help plus the default
};

// In parameter-file order. The model, camera and light are not among them:
// they are the file's and the view's, not the LoD's.
std::span<const ParameterDeclaration> lod_parameter_declarations();
const ParameterDeclaration* find_lod_parameter(const std::string& key);  // nullptr when unknown

// The manual's program (docs/design.md: Level values and the cut): every
// sub-tree boxed, pages of at least 256 texels a side, no flat faces, one
// sizing distance for every level; the commands' --manual (a sweep's
// `manual = true`) sets this.
void set_manual(LodParameters& parameters);

// The levels 1..N the parameters ask for: one per budget where the level mode
// takes budgets (orders_by_bytes), else wanted_levels.
int asked_levels(const LodParameters& parameters);

// Checks every declared range and what binds several parameters (min <= max
// texture size, the camera, the light); throws InputError naming `where`.
void validate_parameters(const LodParameters& parameters, const std::string& where);

// How a level is drawn through `camera`: in `mode`, with the parallax its
// parameters state, lit from the camera (docs/design.md: Rendering).
RenderSettings drawing_settings(const Camera& camera, RenderMode mode, const LodParameters& parameters,
                                int threads);

}  // namespace boxlod
