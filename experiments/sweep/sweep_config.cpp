#include "experiments/sweep/sweep_config.h"

#include "base/csv.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/key_value_lines.h"
#include "base/key_values.h"
#include "base/number_text.h"
#include "base/parallel.h"
#include "data_gen/samples.h"
#include "experiments/sweep/impostor.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/cut/level_modes.h"
#include "toolkit/lod/parameter_file.h"
#include "toolkit/metrics/flip.h"
#include "toolkit/metrics/shot.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

namespace boxlod {
namespace {

constexpr EnumEntry<Baseline> baseline_table[] = {
    {Baseline::simplification, "simplification",
     "the original simplified to each level's triangles (boxlod simplify: edge collapse, then clustering)"},
    {Baseline::simplification_best, "simplification-best",
     "of meshoptimizer's variants (collapse, lock-border, sloppy), the one with the lowest image error at "
     "each level's triangles; results.csv names it in baseline_variant"},
    {Baseline::cgal, "cgal",
     "CGAL's Garland-Heckbert edge collapse on each material welded by position, to each level's triangles "
     "(the budget split by surface area; it stops where the mesh allows no more)"},
    {Baseline::single_box, "single-box", "the whole model as one untextured box in its mean colour"},
    {Baseline::impostor, "impostor",
     "an octahedral impostor: K x K captured directions (impostor_directions), texel = pixel at the sizing "
     "distance, one quad facing the direction nearest the camera"},
    {Baseline::proxy_baked, "proxy-baked",
     "the whole model's geometry simplified as one mesh and drawn with its root box's baked faces (the far "
     "level of Simplygon and Unreal's HLOD), at each level but 0: of meshoptimizer's variants and texel "
     "scales 1, 4 and 16 the one with the lowest image error at the level's triangles or byte budget, baked "
     "for its sizing distance; results.csv names it in baseline_variant"},
    {Baseline::file_lods, "file-lods",
     "a CityJSON model's own coarser LoDs (3DBAG's 1.3 and 1.2 below 2.2), read from the same file: the "
     "official ladder; level k is the k-th below the one read, results.csv's baseline_variant names it (no "
     "rows for other formats)"},
};

}  // namespace

std::span<const EnumEntry<Baseline>> baselines() { return baseline_table; }

constexpr EnumEntry<SizingRule> sizing_table[] = {
    {SizingRule::nearest, "nearest", "one LoD per level, sized for the smallest distance"},
    {SizingRule::each_distance, "each-distance", "an LoD per level and distance, sized for it"},
    {SizingRule::per_level, "per-level",
     "level c sized for the smallest distance x 2^(c-1), with budgets at most x B_1/B_c"},
};

std::span<const EnumEntry<SizingRule>> sizing_rules() { return sizing_table; }

constexpr EnumEntry<KeptImages> kept_images_table[] = {
    {KeptImages::none, "none", "only the CSVs"},
    {KeptImages::lod, "lod", "every LoD render and the original per view"},
    {KeptImages::all, "all", "also a FLIP (or RMSE) heat map per row"},
};

std::span<const EnumEntry<KeptImages>> kept_images() { return kept_images_table; }

std::string sweep_settings(const SweepConfig& config) {
    std::string text;
    auto add = [&](const std::string& key, const std::string& value) { text += key + " = " + value + "\n"; };
    add("width", std::to_string(config.width));
    add("height", std::to_string(config.height));
    add("supersampling", std::to_string(config.supersampling));
    add("ppd", format_number(config.pixels_per_degree));
    add("sizing", enum_name(sizing_rules(), config.sizing));
    add("impostor_directions", std::to_string(config.impostor_directions));
    for (const ParameterDeclaration& d : lod_parameter_declarations())
        if (d.sweep_key) add(d.key, d.format(config.lod));
    return text;
}

namespace {

constexpr NumberRange sweep_image_side_range{16, max_image_side};  // SSIM needs an 11-pixel window
constexpr NumberRange distance_multiple_range{0.01, 1000};         // of the framing distance
constexpr NumberRange supersampling_range{1, max_supersampling};

struct Line {
    const std::string& file;
    const KeyValueLine& line;

    [[noreturn]] void fail(const std::string& what) const {
        throw_input_error(file, "line " + std::to_string(line.line) + ": " + line.key, what);
    }
    std::vector<std::string> items() const {
        if (line.value.find_first_not_of(" \t") == std::string::npos) fail("expected a comma-separated list");
        std::vector<std::string> out = comma_list(line.value);
        if (std::find(out.begin(), out.end(), "") != out.end())
            fail("empty item in the list '" + line.value + "'");
        return out;
    }
    template <typename T>
    T number_in(const NumberRange& range, const std::string& text) const {
        if (const auto v = number_within<T>(text, range)) return *v;
        fail(number_problem<T>(text, range));
    }
    template <typename T>
    T number_in(const NumberRange& range) const {
        return number_in<T>(range, line.value);
    }
    // The value, one name of the enum's table.
    template <typename T>
    T word(std::span<const EnumEntry<T>> table) const {
        T value{};
        if (!parse_enum(table, line.value, value))
            fail("expected " + enum_names(table, ", ", " or ") + ", got '" + line.value + "'");
        return value;
    }
    // Each item a name of the enum's table; unknown words name the accepted ones.
    template <typename T>
    std::vector<T> words(std::span<const EnumEntry<T>> table) const {
        std::vector<T> out;
        for (const std::string& word : items()) {
            T value{};
            if (!parse_enum(table, word, value))
                fail("unknown value '" + word + "' (" + enum_names(table) + ")");
            if (std::find(out.begin(), out.end(), value) == out.end()) out.push_back(value);
        }
        return out;
    }
};

SweepModel model_entry(const Line& line, const std::string& item, const std::filesystem::path& folder) {
    SweepModel model{item, "", ""};
    // The item names the model's rows in results.csv, which a resume reads back as text.
    if (const std::string problem = csv_text_problem(item); !problem.empty())
        line.fail("'" + item + "': " + problem);
    if (item.starts_with("sample:")) {
        model.sample = item.substr(7);
        if (model.sample.empty()) line.fail("'sample:' needs a sample name, e.g. sample:house");
        bool known = false;
        for (const SampleGrammar& sample : sample_grammars()) known = known || sample.name == model.sample;
        if (!known) line.fail("unknown sample '" + model.sample + "' (samples: " + sample_names() + ")");
        return model;
    }
    std::filesystem::path path(item);
    model.path = (path.is_relative() ? folder / path : path).lexically_normal().string();
    return model;
}

// An item of `models`; FILE#* is each object of a city file, as FILE#OBJECT (toolkit/formats/model_io.h).
// A model named twice (also as another spelling of its path) is refused: its rows would be counted twice.
void add_models(SweepConfig& c, const Line& line, const std::string& item,
                const std::filesystem::path& folder) {
    const auto add = [&](const SweepModel& model) {
        for (const SweepModel& known : c.models)
            if (known.name == model.name || (known.path == model.path && known.sample == model.sample))
                line.fail("'" + model.name + "' is the model '" + known.name + "' again");
        c.models.push_back(model);
    };
    if (!item.ends_with("#*")) return add(model_entry(line, item, folder));
    const std::string file = item.substr(0, item.size() - 2);
    for (const std::string& object : object_names(load_model(model_entry(line, file, folder).path)))
        add(model_entry(line, file + "#" + object, folder));
}

// A sweep's own keys, one row each: how its value sets the config. The LoD
// parameters a sweep may set are declared in toolkit/lod/lod_parameters.cpp;
// parsing and the help (sweep_config_keys) read both.
struct SweepKey {
    const char* name;
    void (*set)(SweepConfig& c, const Line& l, const std::filesystem::path& folder);
};

const std::vector<SweepKey>& sweep_keys() {
    using Folder = const std::filesystem::path&;
    static const std::vector<SweepKey> keys = {
        {"models",
         [](SweepConfig& c, const Line& l, Folder folder) {
             for (const std::string& item : l.items()) add_models(c, l, item, folder);
         }},
        {"level_modes",
         [](SweepConfig& c, const Line& l, Folder) { c.level_modes = l.words(level_modes()); }},
        {"box_kinds", [](SweepConfig& c, const Line& l, Folder) { c.box_kinds = l.words(box_kinds()); }},
        {"interpolations",
         [](SweepConfig& c, const Line& l, Folder) { c.interpolations = l.words(interpolations()); }},
        {"levels",
         [](SweepConfig& c, const Line& l, Folder) {
             c.levels.clear();
             if (l.line.value == "all") return;
             std::set<int> levels;
             for (const std::string& item : l.items())
                 levels.insert(l.number_in<int>(parameter_range::current_level, item));
             c.levels.assign(levels.begin(), levels.end());
         }},
        {"views",
         [](SweepConfig& c, const Line& l, Folder) {
             c.views.clear();
             std::vector<std::string> items = l.line.value == "all" ? camera_position_names() : l.items();
             for (const std::string& view : items) {
                 if (view == "all" && items.size() > 1)
                     l.fail("'all' stands alone: it names every camera position");
                 if (!camera_direction(view))
                     l.fail("unknown camera position '" + view + "' (e.g. +X, -Y, +X+Y+Z, or all)");
                 if (std::find(c.views.begin(), c.views.end(), view) == c.views.end())
                     c.views.push_back(view);
             }
         }},
        {"distances",
         [](SweepConfig& c, const Line& l, Folder) {
             c.distances.clear();
             std::set<float> seen;  // each once, in the order given
             for (const std::string& item : l.items()) {
                 float d = l.number_in<float>(distance_multiple_range, item);
                 if (seen.insert(d).second) c.distances.push_back(d);
             }
         }},
        {"render_modes",
         [](SweepConfig& c, const Line& l, Folder) { c.render_modes = l.words(render_modes()); }},
        {"width",
         [](SweepConfig& c, const Line& l, Folder) { c.width = l.number_in<int>(sweep_image_side_range); }},
        {"height",
         [](SweepConfig& c, const Line& l, Folder) { c.height = l.number_in<int>(sweep_image_side_range); }},
        {"supersampling", [](SweepConfig& c, const Line& l,
                             Folder) { c.supersampling = l.number_in<int>(supersampling_range); }},
        {"metrics", [](SweepConfig& c, const Line& l, Folder) { c.metrics = l.words(metrics()); }},
        {"ppd", [](SweepConfig& c, const Line& l,
                   Folder) { c.pixels_per_degree = l.number_in<double>(pixels_per_degree_range); }},
        {"sizing", [](SweepConfig& c, const Line& l, Folder) { c.sizing = l.word(sizing_rules()); }},
        // The manual's program (set_manual, one sizing distance); the keys after it change single settings.
        {"manual",
         [](SweepConfig& c, const Line& l, Folder) {
             if (l.line.value != "true" && l.line.value != "false")
                 l.fail("expected true or false, got '" + l.line.value + "'");
             if (l.line.value == "true") {
                 set_manual(c.lod);
                 c.sizing = SizingRule::nearest;
             }
         }},
        {"impostor_directions",
         [](SweepConfig& c, const Line& l, Folder) {
             c.impostor_directions = l.number_in<int>(NumberRange{2, double(max_impostor_directions)});
         }},
        {"baselines",
         [](SweepConfig& c, const Line& l, Folder) {
             c.baselines = l.line.value == "none" ? std::vector<Baseline>{} : l.words(baselines());
         }},
        {"keep_images", [](SweepConfig& c, const Line& l, Folder) { c.keep_images = l.word(kept_images()); }},
        {"threads",
         [](SweepConfig& c, const Line& l, Folder) { c.threads = l.number_in<int>(thread_count_range); }},
    };
    return keys;
}

}  // namespace

std::vector<std::string> sweep_config_keys() {
    std::vector<std::string> names;
    for (const SweepKey& key : sweep_keys()) names.push_back(key.name);
    for (const ParameterDeclaration& d : lod_parameter_declarations())
        if (d.sweep_key) names.push_back(d.key);
    return names;
}

SweepConfig parse_sweep_config(const std::string& text, const std::string& file) {
    SweepConfig c;
    const std::filesystem::path folder = std::filesystem::path(file).parent_path();
    for (const KeyValueLine& kv : parse_key_value_lines(text, file)) {
        Line line{file, kv};
        if (kv.value.empty()) line.fail("missing value");
        if (const ParameterDeclaration* declared = find_lod_parameter(kv.key)) {
            if (!declared->sweep_key)
                line.fail(
                    "the sweep varies this itself (level_modes, box_kinds, interpolations, levels, "
                    "distances, render_modes)");
            if (std::string problem = declared->parse(kv.value, c.lod); !problem.empty()) line.fail(problem);
            continue;
        }
        auto key = std::find_if(sweep_keys().begin(), sweep_keys().end(),
                                [&](const SweepKey& k) { return kv.key == k.name; });
        if (key == sweep_keys().end()) line.fail("unknown key");
        key->set(c, line, folder);
    }
    if (c.models.empty()) throw_input_error(file, "", "no models (key 'models')");
    validate_parameters(c.lod, file);
    // Budgets apply to the modes that order cuts by bytes (sweep.cpp): with none of them, to nothing.
    if (!c.lod.budgets.empty() && std::none_of(c.level_modes.begin(), c.level_modes.end(), orders_by_bytes))
        throw_input_error(file, "budgets",
                          "no level mode of level_modes orders its cuts by bytes; budgets are for "
                          "error-greedy and hybrid");
    return c;
}

double most_sweep_rows(const SweepConfig& config) {
    const double levels =
        config.levels.empty()
            ? double(std::max<std::size_t>(std::size_t(config.lod.wanted_levels), config.lod.budgets.size()) +
                     1)
            : double(config.levels.size());
    const double variants =
        double(config.level_modes.size() * config.box_kinds.size() * config.interpolations.size());
    const double groups =
        double(config.models.size()) * (variants + double(config.baselines.size())) * levels;
    return groups * double(config.views.size() * config.distances.size() * config.render_modes.size());
}

SweepConfig load_sweep_config(const std::string& path) {
    return parse_sweep_config(read_input_file(path, "sweep config"), path);
}

}  // namespace boxlod
