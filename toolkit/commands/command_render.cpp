#include "base/atomic_write.h"
#include "base/distinct_files.h"
#include "base/key_values.h"
#include "renderer/exr_io.h"
#include "renderer/overlays.h"
#include "toolkit/boxlod.h"
#include "toolkit/commands/commands.h"
#include "toolkit/commands/lod_options.h"
#include "toolkit/commands/render_options.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/formats/model_io.h"

#include <cstdio>

namespace boxlod {

static int run_render(const Arguments& arguments) {
    if (!arguments.has("output")) throw InputError("boxlod render: -o/--output OUT.png is required");
    check_output_file(arguments.text("output"), {".png"});
    if (arguments.has("coverage")) check_output_file(arguments.text("coverage"), {".png"});
    if (arguments.has("exr")) check_output_file(arguments.text("exr"), {".exr"});
    check_distinct_files({{"MODEL", model_file_of(arguments.positionals[0])},
                          {"--split-view", model_file_of(arguments.text("split-view", ""))}},
                         {{"--output", arguments.text("output")},
                          {"--coverage", arguments.text("coverage", "")},
                          {"--exr", arguments.text("exr", "")}});
    Model model = read_model(arguments.positionals[0], city_lod_from(arguments), arguments.integer("level"));
    auto drawable_model = make_drawable_model(model);
    const Drawable& drawable = drawable_model->drawable;
    View view = view_from_arguments(arguments, drawable.bounds);
    Frame frame = make_frame(view.width, view.height, view.background);
    if (arguments.has("split-view")) {
        // The manual's split view: left half this model, right half the other, same camera.
        Model other_model = read_model(arguments.text("split-view"));
        // Two files of one place may keep it relative to different local origins (docs/design.md: Files).
        const Eigen::Vector3f shift = (other_model.origin - model.origin).cast<float>();
        for (Node& node : other_model.nodes)
            for (Primitive& primitive : node.primitives)
                for (Eigen::Vector3f& position : primitive.positions) position += shift;
        auto other_drawable = make_drawable_model(other_model);
        const Drawable& other = other_drawable->drawable;
        RenderSettings left = view.settings, right = view.settings;
        left.scissor_x1 = view.width / 2;
        right.scissor_x0 = view.width / 2;
        render(drawable.batches, left, frame);
        render(other.batches, right, frame);
        draw_divider(frame, view.width / 2, {0, 0, 0});
    } else {
        render(drawable.batches, view.settings, frame);
    }
    if (arguments.has("axes")) {
        Eigen::Vector3f origin = drawable.bounds.min;
        draw_axes(frame, view.settings.camera, origin, drawable.bounds.size().maxCoeff() * 0.5f);
    }
    KeyValues report{text_entry("output", arguments.text("output"))};
    write_png(arguments.text("output"), frame_to_srgb8(frame));
    if (arguments.has("exr")) {
        write_exr(arguments.text("exr"), frame, view.settings.camera);
        report.push_back(text_entry("exr", arguments.text("exr")));
    }
    if (arguments.has("coverage")) {
        write_png(arguments.text("coverage"), coverage_mask(frame));
        report.push_back(text_entry("coverage", arguments.text("coverage")));
    }
    report.push_back(number_entry("width", view.width));
    report.push_back(number_entry("height", view.height));
    report.push_back(float_entry("distance", view.distance));
    report.push_back(text_entry("mode", render_mode_name(view.settings.mode)));
    std::fputs(format_key_values(report).c_str(), stdout);
    return 0;
}

Subcommand render_subcommand() {
    std::vector<Option> options = {
        {"output", "FILE", "PNG image to write (required)", {}, "", 'o'},
        {"exr", "FILE", "also write linear half RGBA + float depth Z as OpenEXR"},
        {"coverage", "FILE", "also write the coverage mask as a PNG"},
        {"axes", "", "draw the coordinate cross (X red, Y green, Z blue) at the model's corner"},
        {"split-view", "MODEL", "left half this model, right half MODEL (the manual's split view)"},
        {"level", "K", "of an LoD chain (build --chain): draw level K, as an MSFT_lod client does",
         NumberRange{0, 63}, "0"},
    };
    options.push_back(city_lod_option());
    for (const Option& o : render_options()) options.push_back(o);
    return {{"render", "MODEL", "Render a model with the deterministic CPU renderer.", options, 1, 1},
            run_render};
}

}  // namespace boxlod
