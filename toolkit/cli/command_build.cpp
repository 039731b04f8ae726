#include "renderer/input_error.h"
#include "toolkit/cli/commands.h"
#include "toolkit/cli/lod_options.h"
#include "toolkit/lod_export.h"
#include "toolkit/model_io.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace boxlod {
namespace {

int run_build(const Arguments& a) {
    LodParameters parameters = lod_parameters_from(a);
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
        KeyValues report{text_entry("name", level_name)};
        report.insert(report.end(), lod.statistics.begin(), lod.statistics.end());
        export_lod(std::move(lod), *session, a.text("output"), level_name, preview, threads);
        session->times.write += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "boxlod build: level %d of %d -> %s\n", level, obtained, level_name.c_str());
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
    Subcommand build{{"build", "MODEL|PARAMS.txt",
             "Build a textured-box LoD: level values, boxes, baked face textures, atlas pages, LoD mesh; writes "
             "NAME.gltf/.bin, NAME_{color,normal,height}_K.png, NAME.params.txt, NAME.preview.png, NAME.stats.txt.",
             {
                 {"output", "OUTDIR", "folder for the files (required)", 'o'},
                 {"name", "NAME", "base name of the files (default: MODEL's stem + _lod)"},
                 {"save-params", "FILE", "write the parameter file and stop"},
                 {"all-levels", "", "write every level 0..N as NAME_L<c>, sharing boxes and baked faces"},
                 {"preview-width", "W", "preview image width (default 1024)"},
                 {"preview-height", "H", "preview image height (default 768)"},
                 {"timings", "", "print the time split (boxes, levels, bake, pack, mesh) in seconds"},
                 {"threads", "N", "threads to use (default: all cores)"},
             },
             1, 1},
            run_build};
    std::vector<Option> lod = lod_options();
    build.command.options.insert(build.command.options.begin() + 3, lod.begin(), lod.end());
    return build;
}

}  // namespace boxlod
