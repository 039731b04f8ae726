#include "toolkit/lod/lod_export.h"

#include "base/atomic_write.h"
#include "base/input_error.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/formats/gltf_io.h"
#include "toolkit/lod/pages/level_pages.h"
#include "toolkit/lod/parameter_file.h"
#include "toolkit/model/framing.h"

#include <filesystem>
#include <regex>

namespace boxlod {

namespace {

// The camera of the parameters, or the default view: +X+Y+Z at the sizing distance.
Camera preview_camera(const Model& original, const LodParameters& p) {
    const Framing framing = model_framing(original);
    if (!p.camera) return framed_camera(framing, {1, 1, 1}, p.distance, p.fovy);
    Camera camera = *p.camera;
    fit_depth_range(camera, (camera.position - framing.center).norm(), framing.radius);
    return camera;
}

}  // namespace

Image8 render_lod_preview(const Lod& lod, const Model& original, const LodParameters& p, int width,
                          int height, int threads) {
    auto drawable = make_drawable_model(lod.model, nullptr, threads);
    RenderSettings settings;
    settings.camera = preview_camera(original, p);
    settings.mode = p.render_mode;
    settings.light = p.light ? *p.light : light_for_camera(settings.camera);
    settings.parallax_scale = p.parallax_scale;
    settings.parallax_bias = p.parallax_bias;
    settings.threads = threads;
    Frame frame = make_frame(width, height, {1, 1, 1});
    render(drawable->drawable.batches, settings, frame);
    return frame_to_srgb8(frame);
}

void name_pages(Lod& lod, const std::string& name) {
    for (int page = 0; page < int(lod.atlas.pages.size()); ++page)
        for (int texture : {lod_page(page).color, lod_page(page).normal, lod_page(page).height})
            lod.model.textures[std::size_t(texture)].name =
                name + "_" + lod.model.textures[std::size_t(texture)].name;
}

void export_lod(Lod lod, const LodParameters& chain_parameters, const std::string& directory,
                const std::string& name, const Image8& preview, int threads, bool binary) {
    namespace fs = std::filesystem;
    // A level's files appear together or not at all: they wait as temporaries
    // until the commit renames them, so even SIGKILL leaves no half level; the
    // folder is made by the first of them and goes with a failed group.
    OutputGroup files;
    auto file = [&](const std::string& suffix) { return (fs::path(directory) / (name + suffix)).string(); };
    name_pages(lod, name);
    LodParameters parameters = chain_parameters;
    parameters.current_level = lod.current_level;
    save_parameters(file(".params.txt"), parameters);
    write_png(file(".preview.png"), preview);
    write_text_atomically(file(".stats.txt"), format_key_values(lod.statistics));
    export_gltf(lod.model, file(binary ? ".glb" : ".gltf"), threads);
    files.commit();
}

bool lod_export_writes(const std::string& file_name, const std::string& name, bool levels) {
    if (file_name.compare(0, name.size(), name) != 0) return false;
    // What export_lod and glTF's buffer and page names append to the name.
    static const std::string files =
        R"((\.(gltf|bin|glb|params\.txt|preview\.png|stats\.txt)|_(color|normal|height)_[0-9]+\.png))";
    static const std::regex suffix(files), level_suffix("_L[0-9]+" + files);
    return std::regex_match(file_name.substr(name.size()), levels ? level_suffix : suffix);
}

}  // namespace boxlod
