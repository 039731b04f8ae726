#include "experiments/sweep/sweep_tables.h"

#include "base/atomic_write.h"
#include "base/csv.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/key_value_lines.h"
#include "toolkit/metrics/metric_registry.h"

#include <libdeflate.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>

namespace boxlod {
namespace {

namespace fs = std::filesystem;

// What each column of results.csv and timings.csv holds, checked when a
// folder's tables are read back (a resumed sweep, --merge): metric columns
// hold metrics, the others are counts unless listed.
CsvColumn column_kind(const std::string& column) {
    static const std::map<std::string, CsvValue> listed = {{"model", CsvValue::text},
                                                           {"level_mode", CsvValue::text},
                                                           {"box_kind", CsvValue::text},
                                                           {"interpolation", CsvValue::text},
                                                           {"view", CsvValue::text},
                                                           {"render_mode", CsvValue::text},
                                                           {"baseline_variant", CsvValue::text},
                                                           {"distance", CsvValue::number},
                                                           {"depth_error", CsvValue::optional_number},
                                                           {"measured_error", CsvValue::optional_number},
                                                           {"build_seconds", CsvValue::number},
                                                           {"render_seconds", CsvValue::number},
                                                           {"metric_seconds", CsvValue::number}};
    if (auto found = listed.find(column); found != listed.end()) return {column, found->second};
    Metric metric;
    if (parse_enum(metrics(), column, metric)) return {column, CsvValue::metric, metric_range(metric)};
    return {column, CsvValue::count};
}

KeyedTable open_table(const std::string& path, const std::vector<std::string>& columns) {
    KeyedTable table{path, columns, {}, {}};
    if (!fs::exists(path)) return table;
    std::vector<CsvColumn> kinds;
    for (const std::string& column : columns) kinds.push_back(column_kind(column));
    std::map<std::string, int> first_line;
    for (CsvRecord& record : read_csv_table(read_input_file(path, "sweep table"), path, kinds)) {
        const std::string line = csv_row(record.fields);
        record.fields.resize(sweep_key_columns().size());
        std::string key = csv_row(record.fields);
        if (auto [first, added] = first_line.emplace(key, record.line); !added)
            throw_input_error(path, "line " + std::to_string(record.line),
                              "the row of line " + std::to_string(first->second) + " again");
        table.rows.emplace(key, line);
        table.file_order.push_back(key);
    }
    return table;
}

// The rows in the sweep's order, then any the file had that this sweep does not make.
void write_table(const KeyedTable& table, const std::vector<std::string>& order) {
    std::string text = csv_row(table.columns) + "\n";
    std::set<std::string> written;
    auto add = [&](const std::string& key) {
        auto row = table.rows.find(key);
        if (row != table.rows.end() && written.insert(key).second) text += row->second + "\n";
    };
    for (const std::string& key : order) add(key);
    for (const std::string& key : table.file_order) add(key);
    write_text_atomically(table.path, text);
}

// File names: the key's words joined by '_', anything but [A-Za-z0-9+-.] replaced.
std::string file_name(std::string name) {
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.' && c != '_')
            c = '_';
    return name + ".png";
}

// The build of boxlod that is running: its executable's size and CRC-32.
// Another build may draw other pixels, so its rows are not this one's.
std::string this_build() {
    std::ifstream in("/proc/self/exe", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in || bytes.empty()) return "unknown";  // no /proc: every build looks alike
    char crc[9];
    std::snprintf(crc, sizeof crc, "%08x", unsigned(libdeflate_crc32(0, bytes.data(), bytes.size())));
    return std::to_string(bytes.size()) + " bytes, crc32 " + crc;
}

// settings.txt: what the folder's rows were made with (sweep_settings) and by
// which build. A re-run with other settings or another build would skip rows
// that no longer answer it. Written with the tables (write_tables).
void check_settings(const fs::path& path, const std::string& settings,
                    const std::string& advice = "use another output folder") {
    if (!fs::exists(path))
        return;  // a new folder (or one from before settings.txt: its rows are taken as they are)
    const std::vector<KeyValueLine> was = parse_key_value_lines(
                                        read_input_file(path.string(), "sweep settings"), path.string()),
                                    is = parse_key_value_lines(settings, "this sweep");
    auto text = [](const std::vector<KeyValueLine>& lines, std::size_t k) {
        return k < lines.size() ? "'" + lines[k].key + " = " + lines[k].value + "'"
                                : std::string("nothing more");
    };
    for (std::size_t k = 0; k < std::max(was.size(), is.size()); ++k)
        if (k >= was.size() || k >= is.size() || was[k].key != is[k].key || was[k].value != is[k].value)
            throw_input_error(path.string(), k < was.size() ? "line " + std::to_string(was[k].line) : "",
                              "the rows here were made with " + text(was, k) + ", this sweep runs with " +
                                  text(is, k) + "; " + advice);
}

// A shard's rows into the merged table: a row two shards both hold must be the
// same. They join no file order: only rows this sweep makes are written.
void merge_rows(KeyedTable& into, const KeyedTable& shard) {
    for (const std::string& key : shard.file_order) {
        const std::string& row = shard.rows.at(key);
        auto [at, added] = into.rows.emplace(key, row);
        if (!added && at->second != row)
            throw_input_error(shard.path, key, "this row differs from another shard's or the merged table's");
    }
}

}  // namespace

const std::vector<std::string>& sweep_key_columns() {
    static const std::vector<std::string> columns = {"model", "level_mode", "box_kind", "interpolation",
                                                     "level", "view",       "distance", "render_mode"};
    return columns;
}

SweepOutput open_output(const SweepConfig& config, const std::string& output_folder,
                        const std::vector<std::string>& result_columns,
                        const std::vector<std::string>& timing_columns) {
    // Kept images are named after their rows' keys made file names: two models whose names differ only
    // where file_name puts '_' (x/t.gltf, x_t.gltf) would write over each other's.
    for (std::size_t a = 0; config.keep_images != KeptImages::none && a < config.models.size(); ++a)
        for (std::size_t b = a + 1; b < config.models.size(); ++b)
            if (file_name(config.models[a].name) == file_name(config.models[b].name))
                throw InputError("keep_images: models '" + config.models[a].name + "' and '" +
                                 config.models[b].name + "' would write the same image files: rename one");
    fs::create_directories(output_folder);
    SweepOutput out{open_table((fs::path(output_folder) / "results.csv").string(), result_columns),
                    open_table((fs::path(output_folder) / "timings.csv").string(), timing_columns),
                    fs::path(output_folder) / "settings.txt",
                    sweep_settings(config) + "boxlod_build = " + this_build() + "\n",
                    {},
                    fs::path(output_folder) / "images",
                    config.keep_images != KeptImages::none};
    check_settings(out.settings_path, out.settings);
    if (out.keep_images) fs::create_directories(out.images);
    return out;
}

void save_image(const SweepOutput& out, const std::string& name, const Image8& image) {
    write_png((out.images / file_name(name)).string(), image);
}

// Rewritten after every group, so an interrupted sweep keeps what it has.
void write_tables(const SweepOutput& out) {
    write_text_atomically(out.settings_path.string(), out.settings);
    write_table(out.results, out.order);
    write_table(out.timings, out.order);
}

void merge_shards(SweepOutput& out, const std::vector<std::string>& shard_folders) {
    for (const std::string& folder : shard_folders) {
        const fs::path results = fs::path(folder) / "results.csv";
        if (!fs::is_regular_file(results))
            throw_input_error(results.string(), "", "no such shard results file");
        // A shard of another sweep (settings or build) would merge rows that do not answer this one.
        const fs::path settings = fs::path(folder) / "settings.txt";
        if (fs::exists(settings) && !fs::is_regular_file(settings))
            throw_input_error(settings.string(), "", "is not a file");
        check_settings(settings, out.settings, "merge only shards of this sweep");
        merge_rows(out.results, open_table(results.string(), out.results.columns));
        KeyedTable timings = open_table((fs::path(folder) / "timings.csv").string(), out.timings.columns);
        // Timings differ from run to run: the first shard's stand.
        for (const std::string& key : timings.file_order) out.timings.rows.emplace(key, timings.rows.at(key));
        if (out.keep_images && fs::is_directory(fs::path(folder) / "images"))
            fs::copy(fs::path(folder) / "images", out.images,
                     fs::copy_options::overwrite_existing | fs::copy_options::recursive);
    }
}

}  // namespace boxlod
