#include "base/atomic_write.h"
#include "base/common_options.h"
#include "base/distinct_files.h"
#include "base/input_error.h"
#include "base/parallel.h"
#include "base/timing.h"
#include "base/utf8.h"
#include "renderer/image.h"
#include "toolkit/commands/commands.h"
#include "toolkit/commands/lod_options.h"
#include "toolkit/commands/viewer_pages.h"
#include "toolkit/formats/gltf_io.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/lod/chain/switch_measures.h"
#include "toolkit/lod/hybrid/draw_calls.h"
#include "toolkit/lod/lod_export.h"
#include "toolkit/lod/parameter_file.h"
#include "toolkit/model/cost.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <future>
#include <limits>
#include <memory>
#include <optional>

namespace boxlod {
namespace {

// The levels 1..N written for the chain's cost, and which of them is the
// finest with pages (its index in `levels` and its level number).
struct ChainCost {
    std::vector<CostParts> levels;
    int finest_textured = -1, finest_textured_level = -1;

    void add(const Lod& lod) {
        if (lod.current_level < 1) return;
        levels.push_back(lod.cost);
        if (finest_textured < 0 && !lod.atlas.pages.empty()) {
            finest_textured = int(levels.size()) - 1;
            finest_textured_level = lod.current_level;
        }
    }
};

// What levels 1..N cost shipped together (a texture shared by levels paid
// once), and their textures against those of the finest level with pages.
KeyValues chain_report(const std::string& name, const ChainCost& written) {
    std::vector<const CostParts*> all;
    for (const CostParts& level : written.levels) all.push_back(&level);
    const ModelCost chain = combined_cost(all);
    KeyValues report{text_entry("name", name + "_chain")};
    const KeyValues cost = cost_entries(chain, "_chain");
    report.insert(report.end(), cost.begin(), cost.end());
    if (written.finest_textured >= 0) {
        const ModelCost finest = combined_cost({&written.levels[std::size_t(written.finest_textured)]});
        report.push_back(number_entry("finest_textured_level", written.finest_textured_level));
        report.push_back(number_entry("chain_texture_ratio",
                                      double(chain.texture_bytes_gpu) / double(finest.texture_bytes_gpu)));
    }
    return report;
}

// A level's stdout block: its name, sizing distance, the later levels it
// stands for (they draw what it draws: chain.h), its errors by distance
// (a chain's: error_by_distance.h), where engines switch to it, in their
// terms (toolkit/lod/chain/switch_measures.h), its statistics.
KeyValues level_report(const std::string& name, const ChainLevel& level, float sizing_distance,
                       const std::optional<LodSwitch>& at, const std::vector<double>& errors) {
    KeyValues report{text_entry("name", name), float_entry("sizing_distance", sizing_distance)};
    if (!level.same_levels.empty())
        report.push_back(numbers_entry(
            "same_as_levels", std::vector<double>(level.same_levels.begin(), level.same_levels.end())));
    if (!errors.empty()) report.push_back(numbers_entry("errors_by_distance", errors));
    if (at)
        report.insert(report.end(), {number_entry("switch_distance", at->distance),
                                     number_entry("screen_coverage", at->screen_coverage),
                                     number_entry("unity_relative_height", at->unity_relative_height),
                                     number_entry("unreal_screen_size", at->unreal_screen_size)});
    report.insert(report.end(), level.lod.statistics.begin(), level.lod.statistics.end());
    return report;
}

// Babylon.js loads at most 10 levels of MSFT_lod, the coarsest (its
// maxLODsToLoad): a chain keeps the 10 finest, the ones drawn nearest.
constexpr int max_chain_levels = 10;
// The nodes a chain may hold before engines import it slowly (docs/cost.md: Draw calls).
constexpr std::size_t max_engine_nodes = 10000;

// Levels 0..N in one .glb/.gltf with MSFT_lod (docs/cost.md: Switching levels),
// each once, those that some distance draws, switching where their error says.
void write_chain(const Arguments& a, Chain& chain, ChainCost& cost) {
    const std::string output = a.text("output");
    const std::string stem = std::filesystem::path(output).stem().string();
    const Bounds bounds = model_bounds(chain.model);
    SwitchedChain switched = switched_levels(chain, switch_error(a), max_chain_levels);
    if (!switched.distances.empty())
        std::fputs(format_key_values({numbers_entry("measured_distances", switched.distances)}).c_str(),
                   stdout);
    std::vector<Model> models;
    std::vector<LodSwitch> switches;
    for (std::size_t k = 0; k < switched.levels.size(); ++k) {
        ChainLevel& level = switched.levels[k];
        const std::string name = stem + "_L" + std::to_string(level.level);
        for (int c : level.same_levels)
            std::fprintf(stderr, "boxlod build: level %d draws what level %d does: the chain has it once\n",
                         c, level.level);
        cost.add(level.lod);
        name_pages(level.lod, name);
        std::optional<LodSwitch> at;
        if (k > 0) {
            at = lod_switch(switched.switch_distances[k], bounds, chain.sizing(level.level));
            switches.push_back(*at);
        }
        const KeyValues report =
            level_report(name, level, chain.sized_parameters(level.level).distance, at,
                         switched.errors.empty() ? std::vector<double>{} : switched.errors[k]);
        std::fputs((format_key_values(report) + "\n").c_str(), stdout);
        models.push_back(a.has("keep-hierarchy") ? std::move(level.lod.model)
                                                 : merge_draw_calls(std::move(level.lod.model), name));
    }
    std::fprintf(stderr,
                 "boxlod build: --chain holds %zu of the %d distinct levels (%d drawn at some distance; "
                 "MSFT_lod clients load at most %d)\n",
                 models.size(), switched.distinct, switched.reachable, max_chain_levels);
    std::vector<const Model*> pointers;
    std::size_t nodes = 0;
    for (const Model& model : models) {
        pointers.push_back(&model);
        nodes += model.nodes.size();
    }
    if (nodes > max_engine_nodes)  // engines import a node as an object: Blender 3.4 did not import 32,254 in
                                   // 8 minutes
        std::fprintf(
            stderr,
            "boxlod build: warning: the chain holds %zu nodes (--keep-hierarchy); engines import each as an "
            "object, and more than %zu import slowly or not at all (docs/cost.md: Draw calls)\n",
            nodes, max_engine_nodes);
    std::vector<std::string> pages;
    {
        const ScopedTimer timer(chain.written.write);
        OutputGroup files;  // the chain and its viewer pages, or nothing
        export_gltf_lods(pointers, switches, output, chain.threads);
        if (a.has("viewer")) pages = write_viewer_pages(output);
        files.commit();
    }
    std::printf("chain = %s\n", output.c_str());
    for (const std::string& page : pages) std::printf("viewer = %s\n", page.c_str());
}

// The levels first..last, each as NAME_L<c> (one level: NAME), a level that
// draws what the one before draws not again (--all-levels: its block names
// it), all placed together once the last is written. Level c is written (preview, glTF, pages) while the next
// are built: writing is partly serial (the .gltf's JSON), so the overlap keeps both cores busy. Files, their
// bytes and the order of the output stay the same.
void write_levels(const Arguments& a, Chain& chain, const std::string& name, int first, int last,
                  ChainCost& cost) {
    const int preview_width = a.integer("preview-width"), preview_height = a.integer("preview-height");
    const Bounds bounds = model_bounds(chain.model);
    const bool all_levels = a.has("all-levels");
    OutputGroup files;          // every level or none: a level that fails leaves the folder as it was (73)
    std::future<void> writing;  // destroyed first: a level being written is done before the group goes
    take_distinct_levels(chain, first, last, std::numeric_limits<int>::max(), [&](ChainLevel level) {
        cost.add(level.lod);
        if (writing.valid()) writing.get();
        // Read here: the chain makes the next level's session while this one is written.
        const LodParameters sized = chain.sized_parameters(level.level);
        const TextureSizing sizing = chain.sizing(level.level);
        writing = std::async(std::launch::async, [&, sized, sizing, level = std::move(level)]() mutable {
            const std::string level_name = all_levels ? name + "_L" + std::to_string(level.level) : name;
            KeyValues report;
            Image8 preview;
            {
                const ScopedTimer timer(chain.written.preview);
                preview = render_lod_preview(level.lod, chain.model, sized, preview_width, preview_height,
                                             chain.threads);
            }
            {
                const ScopedTimer timer(chain.written.write);
                std::optional<LodSwitch> at;  // sized per level: where its texels meet the screen's pixels
                if (!chain.distances.empty() && level.level >= 1)
                    at = lod_switch(sized.distance, bounds, sizing);
                report = level_report(level_name, level, sized.distance, at, {});
                export_lod(std::move(level.lod), chain.parameters(), a.text("output"), level_name, preview,
                           chain.threads, a.has("glb"));
            }
            std::fprintf(stderr, "boxlod build: level %d of %d -> %s\n", level.level, chain.obtained_levels(),
                         level_name.c_str());
            for (int c : level.same_levels)
                std::fprintf(stderr, "boxlod build: level %d draws what level %d does: %s stands for it\n", c,
                             level.level, level_name.c_str());
            std::fputs((format_key_values(report) + (all_levels ? "\n" : "")).c_str(), stdout);
        });
    });
    writing.get();
    files.commit();
}

// --name: one file name, whose longest file (NAME_L63_normal_99.png) still fits a file name.
void check_base_name(const std::string& name) {
    if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos ||
        std::any_of(name.begin(), name.end(), [](char c) { return (unsigned char)(c) < 0x20 || c == 0x7f; }))
        throw InputError("--name: '" + name + "' is not a file name (the files go into OUTDIR)");
    if (!is_utf8(name))
        throw InputError("--name: '" + name + "' is not UTF-8 text (glTF names its files by URIs in UTF-8)");
    if (name.size() > max_output_name_bytes - 32)
        throw InputError("--name: " + std::to_string(name.size()) + " bytes, more than the " +
                         std::to_string(max_output_name_bytes - 32) + " its files' names leave");
}

// --timings: the chain's seconds per step.
void print_timings(const LodTimes& t) {
    KeyValues times{number_entry("time_boxes", t.boxes), number_entry("time_levels", t.levels),
                    number_entry("time_bake", t.bake),   number_entry("time_pack", t.pack),
                    number_entry("time_mesh", t.mesh),   number_entry("time_preview", t.preview),
                    number_entry("time_write", t.write)};
    std::fputs(format_key_values(times).c_str(), stdout);
}

// The model a build reads is none of the files it writes (`-o . --name tree` replaced tree.gltf).
void check_model_kept(const std::string& model, const std::string& folder, const std::string& name,
                      bool all_levels) {
    check_input_kept(
        model, folder, [&](const std::string& file) { return lod_export_writes(file, name, all_levels); },
        "-o " + folder + " and --name " + name);
}

// Options refused where they would do nothing: with --chain, or without it.
void check_options_agree(const Arguments& a, bool chain_file, bool all_levels) {
    if (a.has("level") && all_levels)
        throw InputError(std::string("--level: ") + (chain_file ? "--chain" : "--all-levels") +
                         " writes every level");
    if (a.has("glb") && chain_file)
        throw InputError("--glb: --chain writes one file, named by -o (.glb or .gltf)");
    static constexpr std::pair<const char*, const char*> chain_only[] = {
        {"keep-hierarchy", "a level's own files keep it"},
        {"viewer", "the pages show a chain"},
        {"switch-error", "it places a chain's switch distances"}};
    for (const auto& [option, why] : chain_only)
        if (a.has(option) && !chain_file)
            throw InputError("--" + std::string(option) + " needs --chain (" + why + ")");
}

int run_build(const Arguments& a) {
    LodParameters parameters = lod_parameters_from(a);
    // The model read; a parameter file read may be saved over (it is read whole first).
    const std::vector<std::pair<std::string, std::string>> inputs = {
        {"MODEL", model_file_of(parameters.model)}};
    if (a.has("save-params")) {  // the manual's Save Parameters: no LoD built
        check_output_file(a.text("save-params"));
        check_distinct_files(inputs, {{"--save-params", a.text("save-params")}});
        save_parameters(a.text("save-params"), parameters);
        std::printf("params = %s\n", a.text("save-params").c_str());
        return 0;
    }
    const bool chain_file = a.has("chain");
    if (!a.has("output"))
        throw InputError("boxlod build: -o/--output " + std::string(chain_file ? "OUT.glb" : "OUTDIR") +
                         " is required");
    if (chain_file) {
        check_output_file(a.text("output"), {".glb", ".gltf"});
        check_distinct_files(inputs, {{"--output", a.text("output")}});
    } else {
        check_output_directory(a.text("output"));
    }
    Model model = load_parameters_model(parameters);
    std::string name =
        a.text("name", utf8_or_latin1(std::filesystem::path(parameters.model).stem().string()) + "_lod");
    check_base_name(name);
    const bool all_levels = a.has("all-levels") || chain_file;
    if (!chain_file) check_model_kept(model_file_of(parameters.model), a.text("output"), name, all_levels);
    check_options_agree(a, chain_file, all_levels);
    // Level c is sized as the chain sizes it, however many levels are asked for.
    Chain chain(model, parameters, threads_from(a));
    const int first = all_levels ? 0 : parameters.current_level,
              last = all_levels ? chain.obtained_levels() : first;
    if (last > chain.obtained_levels()) {  // named where it was set: the option, or the parameter file (73)
        const std::string problem = std::to_string(last) + " is past the levels obtained, 0.." +
                                    std::to_string(chain.obtained_levels());
        if (a.has("level")) throw InputError("--level: " + problem);
        throw_input_error(a.has("params") ? a.text("params") : a.positionals[0], "current_level", problem);
    }
    ChainCost cost;
    if (chain_file) {  // nothing is written before the whole chain is built (a budget no cut fits fails its
                       // level)
        write_chain(a, chain, cost);
    } else {
        std::vector<int> levels;
        for (int c = first; c <= last; ++c) levels.push_back(c);
        check_chain_budgets(chain, levels);  // before any level is written
        write_levels(a, chain, name, first, last, cost);
    }
    if (all_levels) std::fputs(format_key_values(chain_report(name, cost)).c_str(), stdout);
    if (a.has("timings")) print_timings(chain.times());
    return 0;
}

}  // namespace

Subcommand build_subcommand() {
    Subcommand build{
        {"build",
         "MODEL|PARAMS.txt",
         "Build a textured-box LoD: level values, boxes, baked face textures, atlas pages, LoD mesh; writes "
         "NAME.gltf/.bin, NAME_{color,normal,height}_K.png, NAME.params.txt, NAME.preview.png, "
         "NAME.stats.txt.",
         {
             {"output", "OUTDIR", "folder for the files (required)", {}, "", 'o'},
             {"name", "NAME", "base name of the files (default: MODEL's stem + _lod)"},
             {"save-params", "FILE", "write the parameter file and stop"},
             {"all-levels", "",
              "write every level 0..N as NAME_L<c> (a level that draws what the one before draws not again: "
              "the block of the one written names it), sharing boxes and baked faces, sized by "
              "--level-distances"},
             {"glb", "",
              "write each level as one NAME.glb, its pages inside, instead of NAME.gltf + .bin + PNGs"},
             {"chain", "",
              "write every level 0..N (each once; at most the 10 finest, as MSFT_lod clients load) into one "
              "file, -o OUT.glb or OUT.gltf: glTF's MSFT_lod, switch hints in extras.MSFT_screencoverage, "
              "shared textures stored once; levels sized by --level-distances"},
             keep_hierarchy_option(),
             switch_error_option(),
             {"viewer", "",
              "with --chain: also write OUT.three.html and OUT.babylon.html beside it, viewers that switch "
              "its levels at its switch distances in three.js and Babylon.js "
              "(docs/cost.md: Switching levels)"},
             {"preview-width", "W", "preview image width", image_side_range, "1024"},
             {"preview-height", "H", "preview image height", image_side_range, "768"},
             {"timings", "",
              "print the time split (boxes, levels, bake, pack, mesh, preview, write) in seconds"},
             threads_option(),
         },
         1,
         1},
        run_build};
    std::vector<Option> lod = lod_options();
    build.command.options.insert(build.command.options.begin() + 3, lod.begin(), lod.end());
    return build;
}

}  // namespace boxlod
