// `boxlod simplify`: the classic baseline, quadric edge-collapse simplification.
#include "base/atomic_write.h"
#include "base/common_options.h"
#include "base/distinct_files.h"
#include "base/parallel.h"
#include "base/timing.h"
#include "experiments/commands/commands.h"
#include "toolkit/boxlod.h"
#include "toolkit/commands/commands.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/hybrid/simplification.h"
#include "toolkit/model/material_merge.h"
#include "toolkit/model/statistics.h"

#include <cstdio>

namespace boxlod {
namespace {

int run_simplify(const Arguments& arguments) {
    const std::string prefix = "boxlod simplify: ";
    if (!arguments.has("output")) throw InputError(prefix + "-o/--output OUT.gltf|OUT.glb is required");
    if (!arguments.has("faces")) throw InputError(prefix + "--faces N is required");
    check_output_file(arguments.text("output"), {".gltf", ".glb"});
    check_distinct_files({{"MODEL", model_file_of(arguments.positionals[0])}},
                         {{"--output", arguments.text("output")}});
    const int faces = arguments.integer("faces", 0);
    SimplifyOptions options;
    options.lock_border = arguments.has("lock-border");
    options.threads = threads_from(arguments);

    Model model = read_model(arguments.positionals[0]);
    auto start = Clock::now();
    Model simplified = simplify_model(model, std::size_t(faces), options);
    double seconds = seconds_since(start);
    // The model was fine; the request is what cannot be met (it said the input was empty).
    if (mesh_counts(simplified).triangles == 0)
        throw InputError("--faces " + std::to_string(faces) + ": simplifying " + arguments.positionals[0] +
                         " to " + std::to_string(faces) + " face(s) keeps no triangle; ask for more");
    if (!arguments.has("keep-materials")) merge_materials(simplified);
    write_model(simplified, arguments.text("output"));

    MeshCounts original = mesh_counts(model), result = mesh_counts(simplified);
    KeyValues report = {text_entry("output", arguments.text("output")),
                        number_entry("faces_original", double(original.faces)),
                        number_entry("faces", double(result.faces)),
                        number_entry("triangles", double(result.triangles)),
                        number_entry("vertices", double(result.vertices)),
                        number_entry("seconds", seconds)};
    print_report(report, arguments);
    return 0;
}

}  // namespace

Subcommand simplify_subcommand() {
    return {
        {"simplify",
         "MODEL",
         "Simplify a model by quadric edge collapse (meshoptimizer) to at most N triangles: the classic "
         "baseline LoD. Textures and the materials still drawn are kept (equal ones merged), geometry is "
         "merged into one node per material.",
         {{"faces", "N", "the number of faces (triangles) to keep (required)", NumberRange{1, 2147483647}},
          {"output", "FILE", "output file, .gltf or .glb (required)", {}, "", 'o'},
          {"lock-border", "", "never move vertices on open mesh borders"},
          threads_option("threads, one material at a time"),
          keep_materials_option(),
          json_option()},
         1,
         1},
        run_simplify};
}

}  // namespace boxlod
