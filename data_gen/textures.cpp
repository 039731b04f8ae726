#include "data_gen/textures.h"

#include "base/random.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>

namespace boxlod {

namespace {

const char* const names[] = {"brick", "plaster", "roof_tiles", "glass", "wood", "stone"};

// A value in [0, 1) for an integer lattice point.
double lattice(std::uint64_t seed, int x, int y) {
    return (mix_bits(hash_combine(hash_combine(seed, std::uint64_t(x)), std::uint64_t(y))) >> 11) * 0x1p-53;
}

// Smooth value noise with `cells` lattice cells across the tile, wrapping
// around so the tile repeats without a seam. u, v in [0, 1).
double value_noise(std::uint64_t seed, double u, double v, int cells) {
    double x = u * cells, y = v * cells;
    int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    double fx = x - x0, fy = y - y0;
    fx = fx * fx * (3 - 2 * fx);
    fy = fy * fy * (3 - 2 * fy);
    auto at = [&](int i, int j) {
        return lattice(seed, ((i % cells) + cells) % cells, ((j % cells) + cells) % cells);
    };
    double top = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * fx;
    double bottom = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * fx;
    return top + (bottom - top) * fy;
}

// Four octaves of value noise, in [0, 1).
double fractal_noise(std::uint64_t seed, double u, double v, int cells) {
    double sum = 0, weight = 0.5, total = 0;
    for (int octave = 0; octave < 4; ++octave, cells *= 2, weight /= 2) {
        sum += weight * value_noise(seed + octave, u, v, cells);
        total += weight;
    }
    return sum / total;
}

// What a texture is at one point: sRGB colour 0..255 and a height 0..1.
struct Sample {
    Eigen::Vector3d color;
    double height;
};

// Rows of blocks in running bond (bricks, ashlar stone): which block a point
// falls in and how far it is from the nearest joint, in texels.
struct Bond {
    int row, column;
    double joint_distance;
};

Bond running_bond(double px, double py, int size, int block_width, int block_height) {
    int row = int(py) / block_height;
    double shifted = px + (row % 2) * block_width / 2.0;
    int column = int(std::floor(shifted / block_width)) % (size / block_width);
    double in_x = std::fmod(shifted, block_width), in_y = py - row * block_height;
    double joint = std::min({in_x, block_width - in_x, in_y, block_height - in_y});
    return {row, column, joint};
}

Eigen::Vector3d vary(const Eigen::Vector3d& color, double amount, double random) {
    return color * (1 + amount * (random * 2 - 1));
}

Sample brick(double px, double py, int size) {
    Bond bond = running_bond(px, py, size, size / 4, size / 16);
    double u = px / size, v = py / size;
    double grain = fractal_noise(11, u, v, 16);
    if (bond.joint_distance < 1.0) return {Eigen::Vector3d(185, 180, 170) * (0.9 + 0.2 * grain), 0.2};
    double tone = lattice(12, bond.column, bond.row);
    Eigen::Vector3d color = vary({150, 68, 48}, 0.18, tone) * (0.85 + 0.3 * grain);
    return {color, 0.8 + 0.2 * std::min(1.0, bond.joint_distance / 2) + 0.05 * grain};
}

Sample plaster(double px, double py, int size) {
    double u = px / size, v = py / size;
    double coarse = fractal_noise(21, u, v, 4), fine = fractal_noise(22, u, v, 32);
    return {Eigen::Vector3d(228, 218, 198) * (0.92 + 0.08 * coarse + 0.05 * fine), 0.5 + 0.3 * fine};
}

Sample roof_tiles(double px, double py, int size) {
    int tile = size / 8;
    int row = int(py) / tile;
    double shifted = px + (row % 2) * tile / 2.0;
    int column = int(std::floor(shifted / tile)) % 8;
    double across = std::fmod(shifted, tile) / tile, down = (py - row * tile) / tile;
    double u = px / size, v = py / size;
    double grain = fractal_noise(31, u, v, 16);
    // Each tile is a rounded ridge, thickest at its lower edge where it overlaps the next row.
    double height = (0.35 + 0.45 * down) * (0.6 + 0.4 * std::sin(across * std::numbers::pi));
    Eigen::Vector3d color =
        vary({168, 74, 44}, 0.15, lattice(32, column, row)) * (0.7 + 0.3 * height / 0.8 + 0.1 * grain);
    return {color, height};
}

Sample glass(double px, double py, int size) {
    double u = px / size, v = py / size;
    // A soft diagonal reflection band over a sky-to-ground gradient.
    double band = std::exp(-std::pow((u + v - 0.9) * 4, 2));
    Eigen::Vector3d color =
        Eigen::Vector3d(70, 92, 112) * (1.15 - 0.35 * v) + Eigen::Vector3d(60, 60, 55) * band;
    return {color + Eigen::Vector3d::Constant(6 * fractal_noise(41, u, v, 8)), 0.5};
}

Sample wood(double px, double py, int size) {
    int plank = size / 8;
    int column = int(px) / plank;
    double u = px / size, v = py / size;
    double in_x = std::fmod(px, plank);
    double rings = std::sin((in_x / plank * 6 + 8 * fractal_noise(51 + column, u, v, 4)) * std::numbers::pi);
    Eigen::Vector3d color = vary({142, 96, 60}, 0.12, lattice(52, column, 0)) * (0.85 + 0.1 * rings);
    bool gap = in_x < 1.0;
    return {gap ? Eigen::Vector3d(color * 0.45) : color, gap ? 0.1 : 0.7 + 0.05 * rings};
}

Sample stone(double px, double py, int size) {
    Bond bond = running_bond(px, py, size, size / 2, size / 4);
    double u = px / size, v = py / size;
    double grain = fractal_noise(61, u, v, 16);
    if (bond.joint_distance < 1.5) return {Eigen::Vector3d(140, 136, 128) * (0.9 + 0.2 * grain), 0.15};
    Eigen::Vector3d color =
        vary({188, 182, 170}, 0.1, lattice(62, bond.column, bond.row)) * (0.85 + 0.25 * grain);
    return {color, 0.75 + 0.15 * std::min(1.0, bond.joint_distance / 4) + 0.1 * grain};
}

struct Recipe {
    const char* name;
    Sample (*sample)(double, double, int);
    float tile_metres;
    double bumpiness;  // how strongly height turns into the normal map
};

const Recipe recipes[] = {
    {"brick", brick, 1.0f, 3.0}, {"plaster", plaster, 2.0f, 1.5}, {"roof_tiles", roof_tiles, 1.0f, 3.0},
    {"glass", glass, 1.5f, 0.2}, {"wood", wood, 1.0f, 2.0},       {"stone", stone, 2.0f, 3.0}};

std::uint8_t to_byte(double value) { return std::uint8_t(std::clamp(std::lround(value), 0L, 255L)); }

}  // namespace

bool is_texture_name(const std::string& name) {
    for (const char* known : names)
        if (name == known) return true;
    return false;
}

std::string texture_names() { return "brick, plaster, roof_tiles, glass, wood, stone"; }

static const Recipe& recipe_of(const std::string& name) {
    for (const Recipe& r : recipes)
        if (name == r.name) return r;
    return recipes[0];
}

float texture_tile_metres(const std::string& name) { return recipe_of(name).tile_metres; }

namespace {

ProceduralTexture make_procedural_texture(const std::string& name, int size) {
    const Recipe* recipe = &recipe_of(name);
    ProceduralTexture texture;
    texture.tile_metres = recipe->tile_metres;
    texture.color = Image8(size, size, 4, 255);
    texture.normal = Image8(size, size, 4, 255);
    std::vector<double> height(std::size_t(size) * size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            Sample sample = recipe->sample(x + 0.5, y + 0.5, size);
            std::uint8_t* pixel = texture.color.at(x, y);
            for (int c = 0; c < 3; ++c) pixel[c] = to_byte(sample.color[c]);
            height[std::size_t(y) * size + x] = sample.height;
        }
    // Normal from the height's slope (wrapping around the tile). Image rows run
    // down, the normal map's +Y up, hence the sign of the y slope.
    auto h = [&](int x, int y) { return height[std::size_t((y + size) % size) * size + (x + size) % size]; };
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            double dx = (h(x + 1, y) - h(x - 1, y)) / 2, dy = (h(x, y + 1) - h(x, y - 1)) / 2;
            Eigen::Vector3d n =
                Eigen::Vector3d(-dx * recipe->bumpiness, dy * recipe->bumpiness, 1).normalized();
            std::uint8_t* pixel = texture.normal.at(x, y);
            for (int c = 0; c < 3; ++c) pixel[c] = to_byte((n[c] * 0.5 + 0.5) * 255);
        }
    return texture;
}

}  // namespace

ProceduralTexture procedural_texture(const std::string& name, int size) {
    // Made once per process: a city derives its few textures into every design.
    static std::mutex mutex;
    static std::map<std::pair<std::string, int>, ProceduralTexture> made;
    std::lock_guard lock(mutex);
    auto found = made.find({name, size});
    if (found == made.end())
        found = made.emplace(std::pair{name, size}, make_procedural_texture(name, size)).first;
    return found->second;
}

}  // namespace boxlod
