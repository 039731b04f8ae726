// Images: plain pixel arrays, PNG in (stb) and out (libspng), sRGB <-> linear.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>
#include "base/input_error.h"

namespace boxlod {

// Row-major, top row first, `channels` interleaved values per pixel.
template <typename T>
struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<T> pixels;

    Image() = default;
    Image(int w, int h, int c, T fill = T{})
        : width(w), height(h), channels(c), pixels(std::size_t(w) * h * c, fill) {}
    T* at(int x, int y) { return &pixels[(std::size_t(y) * width + x) * channels]; }
    const T* at(int x, int y) const { return &pixels[(std::size_t(y) * width + x) * channels]; }
    bool empty() const { return pixels.empty(); }
};
using Image8 = Image<std::uint8_t>;
using Image16 = Image<std::uint16_t>;
using ImageF = Image<float>;

// Images larger than this per side are refused before decoding (a tiny file
// may claim any size); it is also the largest texture page boxlod writes.
constexpr int max_image_side = 16384;
constexpr NumberRange image_side_range{1, max_image_side};

// Decodes PNG/JPEG/BMP/TGA/... bytes to RGBA8; `name` names the source in errors.
Image8 decode_image(std::span<const std::uint8_t> encoded, const std::string& name);
Image8 read_image(const std::string& path);
// The size an image file declares, from its header alone, checked as decoding
// checks it (but for memory): to refuse work on images before decoding them.
struct ImageSize {
    int width = 0, height = 0;
};
ImageSize read_image_size(const std::string& path);

// 8-bit PNG with 1..4 channels; byte-identical for identical pixels.
std::vector<std::uint8_t> encode_png(const Image8& image);
void write_png(const std::string& path, const Image8& image);  // atomic

// 16-bit single-channel PNG (height maps); stb writes 8-bit only.
std::vector<std::uint8_t> encode_png16(const Image16& image);
void write_png16(const std::string& path, const Image16& image);  // atomic
// The first channel at 16 bits (8-bit files are scaled by 257).
Image16 decode_image16(std::span<const std::uint8_t> encoded, const std::string& name);
// A 16-bit single-channel image (a height map) whose 16 bits decode_image16 keeps.
bool is_grey16(std::span<const std::uint8_t> encoded);

// IEC 61966-2-1 decoding of each 8-bit code; inline, as texture fetches decode every texel.
extern const std::array<float, 256> srgb_to_linear_table;
inline float srgb_to_linear(std::uint8_t value) { return srgb_to_linear_table[value]; }
std::uint8_t linear_to_srgb(float value);  // clamps to [0, 1], rounds to nearest

}  // namespace boxlod
