#include "toolkit/commands/lod_options.h"

#include "base/input_error.h"
#include "toolkit/parameters.h"

#include <filesystem>

namespace boxlod {

std::vector<Option> lod_options() {
    const LodParameters defaults;
    auto choice = [](auto table, auto value) { return enum_names(table, ", ", " or ") + " (default " + enum_name(table, value) + ")"; };
    return {
        {"params", "FILE", "load only the parameters from FILE (the model is MODEL)"},
        {"level-mode", "M", choice(level_modes(), defaults.level_mode)},
        {"level", "C", "current level, 0 (original) .. obtained levels (one box) (default 1)", parameter_range::current_level},
        {"wanted-levels", "N", "wanted number of levels for the box modes (default 8)", parameter_range::wanted_levels},
        {"box", "KIND", choice(box_kinds(), defaults.box_kind)},
        {"interpolation", "I", "how box modes map box values to levels: " + choice(interpolations(), defaults.interpolation)},
        {"keep-small-subtrees", "", "beyond the manual: a sub-tree of at most 6 faces keeps its geometry instead of a "
                                    "6-face box, so no level draws more faces than the original"},
        {"keep-cheaper-subtrees", "", "beyond the manual: a node whose sub-tree's mesh costs fewer bytes than its textured "
                                      "box would keeps its geometry, so no box costs more than what it replaces"},
        {"no-crop", "", "keep every baked face whole instead of cropping it to its covered texels (and dropping "
                        "faces with none)"},
        {"fovy", "DEG", "texture sizing: vertical field of view (default 45)", parameter_range::fovy},
        {"distance", "D", "texture sizing: camera distance (default: the distance that frames the model)", parameter_range::distance},
        {"resolution", "R", "texture sizing: screen height in pixels (default 1080)", parameter_range::resolution},
        {"min-texture-size", "S", "smallest LoD texture page (default 256)", parameter_range::texture_size},
        {"max-texture-size", "S", "largest LoD texture page (default 4096)", parameter_range::texture_size},
        {"render-mode", "M", choice(render_modes(), defaults.render_mode) + "; untextured LoDs are not baked"},
        {"parallax-scale", "S", "parallax height scale (default 0.04)", parameter_range::parallax},
        {"parallax-bias", "B", "parallax height bias (default -0.02)", parameter_range::parallax},
    };
}

namespace {
bool is_parameter_file(const std::string& path) { return std::filesystem::path(path).extension() == ".txt"; }

}  // namespace

LodParameters lod_parameters_from(const Arguments& a) {
    LodParameters p;
    const std::string& input = a.positionals[0];
    if (is_parameter_file(input)) {
        p = load_parameters(input);
        if (p.model.empty()) throw_input_error(input, "", "the parameter file names no model (key 'model')");
    } else {
        if (a.has("params")) p = load_parameters(a.text("params"));
        p.model = input;
    }
    auto word = [&](const char* option, auto table, auto& field) {
        if (a.has(option) && !parse_enum(table, a.text(option), field))
            throw InputError(std::string("--") + option + ": unknown value '" + a.text(option) + "' (" + enum_names(table) + ")");
    };
    word("level-mode", level_modes(), p.level_mode);
    word("box", box_kinds(), p.box_kind);
    word("interpolation", interpolations(), p.interpolation);
    word("render-mode", render_modes(), p.render_mode);
    if (a.has("keep-small-subtrees")) p.keep_small_subtrees = true;
    if (a.has("keep-cheaper-subtrees")) p.keep_cheaper_subtrees = true;
    if (a.has("no-crop")) p.crop_faces = false;
    p.current_level = a.integer("level", p.current_level);
    p.wanted_levels = a.integer("wanted-levels", p.wanted_levels);
    p.fovy = float(a.number("fovy", p.fovy));
    p.distance = float(a.number("distance", p.distance));
    p.resolution = float(a.number("resolution", p.resolution));
    p.min_texture_size = a.integer("min-texture-size", p.min_texture_size);
    p.max_texture_size = a.integer("max-texture-size", p.max_texture_size);
    p.parallax_scale = float(a.number("parallax-scale", p.parallax_scale));
    p.parallax_bias = float(a.number("parallax-bias", p.parallax_bias));
    validate_parameters(p, "command line");
    return p;
}


}  // namespace boxlod
