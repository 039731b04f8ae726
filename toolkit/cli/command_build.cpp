#include "renderer/input_error.h"
#include "toolkit/cli/commands.h"
#include "toolkit/lod_export.h"
#include "toolkit/model_io.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace boxlod {
namespace {

bool is_parameter_file(const std::string& path) { return std::filesystem::path(path).extension() == ".txt"; }

// Parameters: from a parameter file (model and all, or --params for parameters
// only), then every option given on the command line on top.
LodParameters parameters_from(const Arguments& a) {
    LodParameters p;
    const std::string& input = a.positionals[0];
    if (is_parameter_file(input)) {
        p = load_parameters(input);
        if (p.model.empty()) throw_input_error(input, "", "the parameter file names no model (key 'model')");
    } else {
        if (a.has("params")) p = load_parameters(a.text("params"));
        p.model = input;
    }
    auto word = [&](const char* option, auto parse, auto& field, const char* known) {
        if (a.has(option) && !parse(a.text(option), field))
            throw InputError(std::string("--") + option + ": unknown value '" + a.text(option) + "' (" + known + ")");
    };
    word("level-mode", parse_level_mode, p.level_mode,
         "top-down, bottom-up, bottom-up-siblings, box-volume, box-area, box-diagonal, box-max-extent");
    word("box", parse_box_kind, p.box_kind, "scope, expanded, minimal");
    word("interpolation", parse_interpolation, p.interpolation, "linear, log, rank");
    word("render-mode", parse_render_mode, p.render_mode, "untextured, normal, parallax, pom");
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

int run_build(const Arguments& a) {
    LodParameters parameters = parameters_from(a);
    if (a.has("save-params")) {  // the manual's Save Parameters: no LoD built
        save_parameters(a.text("save-params"), parameters);
        std::printf("params = %s\n", a.text("save-params").c_str());
        return 0;
    }
    if (!a.has("output")) throw InputError("boxlod build: -o/--output OUTDIR is required");
    int threads = a.integer("threads", 0);
    int preview_width = a.integer("preview-width", 1024), preview_height = a.integer("preview-height", 768);
    if (threads < 0 || preview_width < 1 || preview_height < 1) throw InputError("--threads/--preview-*: expected positive numbers");
    Model model = load_model(parameters.model);
    std::string name = a.text("name", std::filesystem::path(parameters.model).stem().string() + "_lod");
    auto session = start_lod(model, parameters, threads);
    int obtained = session->levels.obtained_levels;
    std::vector<int> levels;
    if (a.has("all-levels"))
        for (int c = 0; c <= obtained; ++c) levels.push_back(c);
    else
        levels.push_back(parameters.current_level);
    for (int level : levels) {
        Lod lod = build_lod(*session, level, threads);
        std::string level_name = a.has("all-levels") ? name + "_L" + std::to_string(level) : name;
        auto start = std::chrono::steady_clock::now();
        Image8 preview = render_lod_preview(lod, *session, preview_width, preview_height, threads);
        export_lod(lod, *session, a.text("output"), level_name, preview, threads);
        session->times.write += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "boxlod build: level %d of %d -> %s\n", level, obtained, level_name.c_str());
        KeyValues report{text_entry("name", level_name)};
        report.insert(report.end(), lod.statistics.begin(), lod.statistics.end());
        std::fputs((format_key_values(report) + (levels.size() > 1 ? "\n" : "")).c_str(), stdout);
    }
    if (a.has("timings")) {
        const LodTimes& t = session->times;
        KeyValues times{number_entry("time_boxes", t.boxes), number_entry("time_levels", t.levels),
                        number_entry("time_bake", t.bake), number_entry("time_pack", t.pack),
                        number_entry("time_mesh", t.mesh), number_entry("time_write", t.write)};
        std::fputs(format_key_values(times).c_str(), stdout);
    }
    return 0;
}

}  // namespace

Subcommand build_subcommand() {
    return {{"build", "MODEL|PARAMS.txt",
             "Build a textured-box LoD: level values, boxes, baked face textures, atlas pages, LoD mesh; writes "
             "NAME.gltf/.bin, NAME_{color,normal,height}_K.png, NAME.params.txt, NAME.preview.png, NAME.stats.txt.",
             {
                 {"output", "OUTDIR", "folder for the files (required)", 'o'},
                 {"name", "NAME", "base name of the files (default: MODEL's stem + _lod)"},
                 {"params", "FILE", "load only the parameters from FILE (the model is MODEL)"},
                 {"save-params", "FILE", "write the parameter file and stop"},
                 {"level-mode", "M", "top-down (default) | bottom-up | bottom-up-siblings | box-volume | box-area | box-diagonal | box-max-extent"},
                 {"level", "C", "current level, 0 (original) .. obtained levels (one box) (default 1)"},
                 {"wanted-levels", "N", "wanted number of levels for the box modes (default 8)"},
                 {"box", "KIND", "scope | expanded (default) | minimal"},
                 {"interpolation", "I", "linear (default) | log | rank: how box modes map box values to levels"},
                 {"fovy", "DEG", "texture sizing: vertical field of view (default 45)"},
                 {"distance", "D", "texture sizing: camera distance (default: the distance that frames the model)"},
                 {"resolution", "R", "texture sizing: screen height in pixels (default 1080)"},
                 {"min-texture-size", "S", "smallest LoD texture page (default 256)"},
                 {"max-texture-size", "S", "largest LoD texture page (default 4096)"},
                 {"render-mode", "M", "untextured (no baking) | normal (default) | parallax | pom"},
                 {"parallax-scale", "S", "parallax height scale (default 0.04)"},
                 {"parallax-bias", "B", "parallax height bias (default -0.02)"},
                 {"all-levels", "", "write every level 0..N as NAME_L<c>, sharing boxes and baked faces"},
                 {"preview-width", "W", "preview image width (default 1024)"},
                 {"preview-height", "H", "preview image height (default 768)"},
                 {"timings", "", "print the time split (boxes, levels, bake, pack, mesh) in seconds"},
                 {"threads", "N", "threads to use (default: all cores)"},
             },
             1, 1},
            run_build};
}

}  // namespace boxlod
