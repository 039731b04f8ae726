// A sweep's output folder as tables: results.csv and timings.csv keyed by
// row, settings.txt, the kept images. Opened (checked when read back: each
// column's values, no row twice, the settings and build the rows were made
// with), rewritten whole after every group, merged from shards' folders.
// The columns are experiments/sweep/sweep.h's, passed in: the sweep sits on this.
#pragma once
#include "experiments/sweep/sweep_config.h"
#include "renderer/image.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace boxlod {

// A CSV whose rows are found by their key columns (the first ones).
struct KeyedTable {
    std::string path;
    std::vector<std::string> columns;
    std::map<std::string, std::string> rows;  // key -> the whole line
    std::vector<std::string> file_order;      // keys as they were in the file
};

// The results table: results.csv and timings.csv keyed by row, the images kept,
// and every row key of the cross product so far, in the sweep's order.
struct SweepOutput {
    KeyedTable results, timings;
    std::filesystem::path settings_path;
    std::string settings;
    std::vector<std::string> order;
    std::filesystem::path images;
    bool keep_images = false;
};

// The columns both tables start with, which find a row: the cross product's dimensions.
const std::vector<std::string>& sweep_key_columns();
// The folder's tables as far as they exist. Throws InputError for rows that do
// not read back, or a settings.txt from other settings or another build.
SweepOutput open_output(const SweepConfig& config, const std::string& output_folder,
                        const std::vector<std::string>& result_columns,
                        const std::vector<std::string>& timing_columns);
// A kept image, named after its row key.
void save_image(const SweepOutput& out, const std::string& name, const Image8& image);
// settings.txt, results.csv and timings.csv, each written atomically.
void write_tables(const SweepOutput& out);
// Reads the shards' results, timings and kept images (tables with the output's columns) into the output.
void merge_shards(SweepOutput& out, const std::vector<std::string>& shard_folders);

}  // namespace boxlod
