#include "renderer/image.h"

#include "base/atomic_write.h"
#include "base/input_error.h"
#include "base/input_file.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

// stb_image_write's zlib stream compressor and settings; libstb exports them, the header keeps them private.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int data_len, int* out_len, int quality);
extern "C" int stbi_write_png_compression_level;
extern "C" int stbi_write_force_png_filter;

namespace boxlod {
namespace {
// The header read before decoding: no allocation for a size the file only claims.
void check_image_header(std::span<const std::uint8_t> encoded, const std::string& name) {
    int width = 0, height = 0, channels = 0;
    if (encoded.size() > std::size_t(std::numeric_limits<int>::max())) throw_input_error(name, "", "image file too large");
    if (!stbi_info_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels))
        throw_input_error(name, "", std::string("cannot decode image: ") + stbi_failure_reason());
    if (width > max_image_side || height > max_image_side)
        throw_input_error(name, "", "image is " + std::to_string(width) + "x" + std::to_string(height) + " pixels, more than " +
                                        std::to_string(max_image_side) + " per side");
}
}  // namespace

bool is_grey16(std::span<const std::uint8_t> encoded) {
    int width = 0, height = 0, channels = 0, size = int(std::min<std::size_t>(encoded.size(), std::numeric_limits<int>::max()));
    return stbi_is_16_bit_from_memory(encoded.data(), size) && stbi_info_from_memory(encoded.data(), size, &width, &height, &channels) &&
           channels == 1;
}

Image8 decode_image(std::span<const std::uint8_t> encoded, const std::string& name) {
    check_image_header(encoded, name);
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
    std::string bytes = read_input_file(path, "image file");
    return decode_image({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, path);
}

namespace {
// Baked pages are mostly flat colour: no row filter and a medium zlib level
// write them twice as fast as stb's defaults, and smaller (measured on 4096^2 pages).
constexpr int png_filter = 0, png_level = 5;
const bool png_settings = [] {
    stbi_write_force_png_filter = png_filter;
    stbi_write_png_compression_level = png_level;
    return true;
}();
}  // namespace

std::vector<std::uint8_t> encode_png(const Image8& image) {
    (void)png_settings;
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
void append_be32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {  // PNG specification, annex D
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xffffffffu;
    for (std::size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xff] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

void append_chunk(std::vector<std::uint8_t>& png, const char* type, const std::vector<std::uint8_t>& data) {
    append_be32(png, std::uint32_t(data.size()));
    std::size_t start = png.size();
    png.insert(png.end(), type, type + 4);
    png.insert(png.end(), data.begin(), data.end());
    append_be32(png, crc32(png.data() + start, png.size() - start));
}
}  // namespace

std::vector<std::uint8_t> encode_png16(const Image16& image) {
    // Rows with filter type 0 (none), samples big-endian.
    std::vector<std::uint8_t> raw;
    raw.reserve(std::size_t(image.height) * (1 + image.width * 2));
    for (int y = 0; y < image.height; ++y) {
        raw.push_back(0);
        for (int x = 0; x < image.width; ++x) {
            std::uint16_t v = image.at(x, y)[0];
            raw.push_back(std::uint8_t(v >> 8));
            raw.push_back(std::uint8_t(v & 0xff));
        }
    }
    int compressed_size = 0;
    unsigned char* compressed = stbi_zlib_compress(raw.data(), int(raw.size()), &compressed_size, png_level);
    if (!compressed) throw std::runtime_error("PNG encoding failed");
    std::vector<std::uint8_t> zlib(compressed, compressed + compressed_size);
    std::free(compressed);
    std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<std::uint8_t> header;
    append_be32(header, std::uint32_t(image.width));
    append_be32(header, std::uint32_t(image.height));
    header.insert(header.end(), {16, 0, 0, 0, 0});  // 16-bit greyscale, deflate, adaptive filtering, no interlace
    append_chunk(png, "IHDR", header);
    append_chunk(png, "IDAT", zlib);
    append_chunk(png, "IEND", {});
    return png;
}

void write_png16(const std::string& path, const Image16& image) { write_file_atomically(path, encode_png16(image)); }

Image16 decode_image16(std::span<const std::uint8_t> encoded, const std::string& name) {
    check_image_header(encoded, name);
    int width = 0, height = 0, channels = 0;
    stbi_us* data = stbi_load_16_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels, 1);
    if (!data) throw_input_error(name, "", std::string("cannot decode image: ") + stbi_failure_reason());
    Image16 image(width, height, 1);
    std::copy(data, data + image.pixels.size(), image.pixels.begin());
    stbi_image_free(data);
    return image;
}

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
