#include "base/atomic_write.h"
#include "base/common_options.h"
#include "base/distinct_files.h"
#include "base/key_values.h"
#include "base/memory_budget.h"
#include "base/parallel.h"
#include "experiments/commands/commands.h"
#include "toolkit/commands/render_options.h"
#include "toolkit/metrics/heatmap.h"
#include "toolkit/metrics/image_metrics.h"
#include "toolkit/metrics/metric_registry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace boxlod {

namespace {

std::vector<Metric> metrics_option(const std::string& list) {
    if (list.empty()) throw InputError("boxlod compare: --metric: expected a list such as rmse,psnr");
    return parse_metrics(comma_list(list), "boxlod compare: --metric");
}

void require_same_size(const ImageSize& a, const std::string& a_name, const ImageSize& b,
                       const std::string& b_name) {
    if (a.width == b.width && a.height == b.height) return;
    throw_input_error(b_name, "",
                      std::to_string(b.width) + "x" + std::to_string(b.height) + " differs in size from " +
                          a_name + " (" + std::to_string(a.width) + "x" + std::to_string(a.height) + ")");
}

// A number, or `inf` (a JSON string) for the PSNR of identical images.
KeyValue metric_entry(const std::string& key, double value) {
    if (std::isinf(value)) return {key, value > 0 ? "inf" : "-inf", false};
    return number_entry(key, value);
}

// The options of the coverages, before any image is read: an option that nothing reads is a mistake,
// said rather than ignored.
void check_coverage_options(const Arguments& arguments, bool read) {
    for (const char* option : {"mask-a", "mask-b", "background"})
        if (!read && arguments.has(option))
            throw InputError(std::string("--") + option + ": only the metrics iou and flip_covered read it");
    if (arguments.has("mask-a") != arguments.has("mask-b"))
        throw InputError("boxlod compare: --mask-a and --mask-b go together");
    if (arguments.has("mask-a") && arguments.has("background"))
        throw InputError("--background: the masks give the coverages, so it is not read with --mask-a");
}

// The two coverages iou and flip_covered read: from --mask-a/--mask-b, else the pixels that differ from the
// background.
std::pair<Coverage, Coverage> silhouettes(const Arguments& arguments, const Image8& a, const Image8& b) {
    if (arguments.has("mask-a")) {
        Image8 mask_a = read_image(arguments.text("mask-a")), mask_b = read_image(arguments.text("mask-b"));
        require_same_size({a.width, a.height}, arguments.positionals[0], {mask_a.width, mask_a.height},
                          arguments.text("mask-a"));
        require_same_size({a.width, a.height}, arguments.positionals[0], {mask_b.width, mask_b.height},
                          arguments.text("mask-b"));
        return {coverage_from_mask(mask_a), coverage_from_mask(mask_b)};
    }
    // boxlod render's background, white unless told otherwise (sRGB components in [0, 1]).
    Eigen::Vector3f srgb = parse_vector3("background", arguments.text("background"), colour_range);
    std::array<std::uint8_t, 3> background{};
    for (int c = 0; c < 3; ++c) background[c] = std::uint8_t(std::lround(srgb[c] * 255));
    return {coverage_from_background(a, background), coverage_from_background(b, background)};
}

int run_compare(const Arguments& arguments) {
    const std::string& a_name = arguments.positionals[0];
    const std::string& b_name = arguments.positionals[1];
    const std::vector<Metric> asked = metrics_option(arguments.text("metric", enum_names(metrics(), ",")));
    std::string heatmap_metric = arguments.text("heatmap-metric");
    if (heatmap_metric != "flip" && heatmap_metric != "rmse")
        throw InputError("boxlod compare: --heatmap-metric: expected flip or rmse, got '" + heatmap_metric +
                         "'");
    if (arguments.has("heatmap")) check_output_file(arguments.text("heatmap"), {".png"});
    check_distinct_files({{"IMAGE_A", a_name},
                          {"IMAGE_B", b_name},
                          {"--mask-a", arguments.text("mask-a", "")},
                          {"--mask-b", arguments.text("mask-b", "")}},
                         {{"--heatmap", arguments.text("heatmap", "")}});
    auto asks = [&](Metric m) { return std::find(asked.begin(), asked.end(), m) != asked.end(); };
    check_coverage_options(arguments, asks(Metric::iou) || asks(Metric::flip_covered));
    const double ppd = arguments.number("ppd");
    int threads = threads_from(arguments);

    // The sizes the files declare, checked before either is decoded (two 16384x16384 PNGs of under 1 MB were
    // decoded for 41 s).
    const ImageSize size = read_image_size(a_name);
    require_same_size(size, a_name, read_image_size(b_name), b_name);
    check_memory("boxlod compare: measuring two " + std::to_string(size.width) + "x" +
                     std::to_string(size.height) + " images",
                 metrics_memory(size.width, size.height));
    Image8 a = read_image(a_name), b = read_image(b_name);
    if (asks(Metric::ssim) && (a.width < 11 || a.height < 11))
        throw_input_error(a_name, "", "SSIM needs images of at least 11x11 pixels");
    std::optional<std::pair<Coverage, Coverage>> coverages;
    if (asks(Metric::iou) || asks(Metric::flip_covered)) coverages = silhouettes(arguments, a, b);

    // A FLIP heat map needs FLIP's error map: measured once, with the metrics asked for or after them.
    std::vector<Metric> measured_metrics = asked;
    if (arguments.has("heatmap") && heatmap_metric == "flip" && !asks(Metric::flip))
        measured_metrics.push_back(Metric::flip);
    MetricPair pair{a, b};
    if (coverages) {
        pair.reference_coverage = &coverages->first;
        pair.test_coverage = &coverages->second;
    }
    pair.pixels_per_degree = ppd;
    pair.threads = threads;
    MetricValues measured = measure_metrics(measured_metrics, pair);
    KeyValues report;
    for (std::size_t i = 0; i < asked.size(); ++i)
        report.push_back(metric_entry(enum_name(metrics(), asked[i]), measured.values[i]));
    if (arguments.has("heatmap")) {
        Plane error = heatmap_metric == "flip" ? std::move(*measured.flip_error) : rgb_error_map(a, b);
        write_png(arguments.text("heatmap"), error_heatmap(error));
        report.push_back(text_entry("heatmap", arguments.text("heatmap")));
    }
    print_report(report, arguments);
    return 0;
}

}  // namespace

Subcommand compare_subcommand() {
    return {
        {"compare",
         "A.png B.png",
         "Compare two images of the same size: RMSE and PSNR (dB) of the sRGB values in [0, 1] (psnr = inf "
         "for identical images), SSIM on BT.601 luma (as scikit-image's structural_similarity, Gaussian "
         "sigma 1.5), mean FLIP (LDR), and the silhouette IoU.",
         {{"metric", "LIST",
           "comma-separated metrics among " + enum_names(metrics(), ",") + " (default: all)"},
          {"heatmap", "FILE", "write a PNG of the per-pixel error (black, red, yellow, white = 0 .. 1)"},
          {"heatmap-metric", "NAME", "the heat map's error: flip or rmse (per-pixel RMS over RGB)",
           std::nullopt, "flip"},
          {"ppd", "N", "FLIP's pixels per degree of visual angle", pixels_per_degree_range, "67"},
          {"mask-a", "FILE",
           "coverage mask of A for iou and flip_covered (covered where > 127; e.g. from render --coverage)"},
          {"mask-b", "FILE", "coverage mask of B for iou and flip_covered"},
          {"background", "R,G,B",
           "without masks, iou and flip_covered count pixels differing from this sRGB colour in [0, 1] (the "
           "render's background)",
           std::nullopt, "1,1,1"},
          threads_option(),
          json_option()},
         2,
         2},
        run_compare};
}

}  // namespace boxlod
