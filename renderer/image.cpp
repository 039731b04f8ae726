#include "renderer/image.h"

#include "renderer/atomic_write.h"
#include "renderer/input_error.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>

namespace boxlod {

Image8 decode_image(std::span<const std::uint8_t> encoded, const std::string& name) {
    int width = 0, height = 0, channels_in_file = 0;
    stbi_uc* data = stbi_load_from_memory(encoded.data(), int(encoded.size()), &width, &height,
                                          &channels_in_file, 4);
    if (!data) throw_input_error(name, "", std::string("cannot decode image: ") + stbi_failure_reason());
    Image8 image(width, height, 4);
    std::copy(data, data + image.pixels.size(), image.pixels.begin());
    stbi_image_free(data);
    return image;
}

Image8 read_image(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw_input_error(path, "", "cannot open image file");
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return decode_image(bytes, path);
}

std::vector<std::uint8_t> encode_png(const Image8& image) {
    std::vector<std::uint8_t> bytes;
    auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        out->insert(out->end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
    };
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, image.channels, image.pixels.data(),
                                image.width * image.channels))
        throw std::runtime_error("PNG encoding failed");
    return bytes;
}

void write_png(const std::string& path, const Image8& image) { write_file_atomically(path, encode_png(image)); }

namespace {
std::array<float, 256> make_srgb_table() {
    std::array<float, 256> table{};
    for (int i = 0; i < 256; ++i) {
        double c = i / 255.0;  // IEC 61966-2-1
        table[i] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return table;
}
const std::array<float, 256> srgb_table = make_srgb_table();
}  // namespace

float srgb_to_linear(std::uint8_t value) { return srgb_table[value]; }

std::uint8_t linear_to_srgb(float value) {
    // Binary search over the decode table's midpoints: exact inverse of srgb_to_linear
    // for every 8-bit value, and no pow() per pixel.
    static const std::array<float, 255> midpoints = [] {
        std::array<float, 255> m{};
        for (int i = 0; i < 255; ++i) {
            double a = srgb_table[i], b = srgb_table[i + 1];
            double ea = a <= 0.0031308 ? a * 12.92 : 1.055 * std::pow(a, 1 / 2.4) - 0.055;
            double eb = b <= 0.0031308 ? b * 12.92 : 1.055 * std::pow(b, 1 / 2.4) - 0.055;
            double mid = (ea + eb) / 2;  // halfway in encoded space = round to nearest
            m[i] = float(mid <= 0.04045 ? mid / 12.92 : std::pow((mid + 0.055) / 1.055, 2.4));
        }
        return m;
    }();
    if (!(value > 0.0f)) return 0;
    return std::uint8_t(std::upper_bound(midpoints.begin(), midpoints.end(), value) - midpoints.begin());
}

}  // namespace boxlod
