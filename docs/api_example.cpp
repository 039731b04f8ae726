// boxlod as a library (toolkit/boxlod.h): a building's hybrid chain, a level within
// 5 % of its bytes, and how that level looks against the original from twice
// the framing distance. Usage: api_example MODEL OUT.glb
#include "toolkit/boxlod.h"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: api_example MODEL OUT.glb\n");
        return 2;
    }
    try {
        const boxlod::Model model = boxlod::read_model(argv[1]);
        boxlod::LodParameters parameters;
        parameters.level_mode = boxlod::LevelMode::hybrid;  // box, simplified sub-tree or geometry per part
        for (const boxlod::Level& level : boxlod::build_chain(model, parameters))
            std::printf("chain level %d from %.1f m\n", level.level, level.switch_distance);
        parameters.budgets = {{true, 0.05}};  // 5 % of the original's bytes
        const boxlod::Level level = boxlod::build_levels_by_budget(model, parameters).front();
        boxlod::write_model(level.model, argv[2]);
        const boxlod::Viewpoint view{.direction = {1, 1, 1}, .distance = 2};
        const boxlod::Shot original = boxlod::render_model(model, model, view);
        const boxlod::Shot drawn = boxlod::render_model(level.model, model, view);
        const boxlod::Comparison difference = boxlod::compare_renders(original, drawn);
        std::printf("level 1: %s bytes, FLIP over covered pixels %.3f, silhouette IoU %.3f\n",
                    boxlod::value_of(level.statistics, "bytes_lod").c_str(), difference.flip_covered,
                    difference.iou);
        return 0;
    } catch (const boxlod::InputError& error) {
        std::fprintf(stderr, "api_example: %s\n", error.what());
        return 2;
    }
}
