#include "toolkit/commands/commands.h"

#include "base/common_options.h"
#include "toolkit/boxlod.h"
#include "toolkit/commands/lod_options.h"
#include "toolkit/model/statistics.h"

#include <cstdio>

namespace boxlod {

static int run_info(const Arguments& arguments) {
    Model model = read_model(arguments.positionals[0], city_lod_from(arguments));
    KeyValues statistics = model_statistics(model);
    statistics.push_back(number_entry("lod", model.is_lod));
    print_report(statistics, arguments);
    return 0;
}

Subcommand info_subcommand() {
    return {
        {"info",
         "MODEL",
         "Read a model (glTF, CityJSON, FBX, OBJ, DAE, PLY, OFF, 3DS, IFC, ...) and print its statistics.",
         {json_option(), city_lod_option()},
         1,
         1},
        run_info};
}

}  // namespace boxlod
