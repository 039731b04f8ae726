#include "base/atomic_write.h"
#include "base/distinct_files.h"
#include "toolkit/boxlod.h"
#include "toolkit/commands/commands.h"
#include "toolkit/commands/lod_options.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/model/material_merge.h"

#include <cstdio>

namespace boxlod {

static int run_convert(const Arguments& arguments) {
    if (!arguments.has("output"))
        throw InputError("boxlod convert: -o/--output OUT.gltf|OUT.glb is required");
    check_output_file(arguments.text("output"), {".gltf", ".glb"});
    check_distinct_files({{"MODEL", model_file_of(arguments.positionals[0])}},
                         {{"--output", arguments.text("output")}});
    Model model =
        read_model(arguments.positionals[0], city_lod_from(arguments));  // through the library's face
    if (!arguments.has("keep-materials")) merge_materials(model);
    write_model(model, arguments.text("output"));
    std::printf("output = %s\n", arguments.text("output").c_str());
    return 0;
}

Subcommand convert_subcommand() {
    return {{"convert",
             "MODEL",
             "Convert any model boxlod reads into glTF (.gltf + .bin + textures, or one .glb), hierarchy, "
             "scopes and rules kept; equal materials merged, unused ones dropped.",
             {{"output", "FILE", "output file, .gltf or .glb (required)", {}, "", 'o'},
              keep_materials_option(),
              city_lod_option()},
             1,
             1},
            run_convert};
}

}  // namespace boxlod
