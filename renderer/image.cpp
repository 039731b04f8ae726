#include "renderer/image.h"

#include "base/atomic_write.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/memory_budget.h"

#include <spng.h>
#include <stb_image.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <stdexcept>

namespace boxlod {
namespace {
std::uint32_t big_endian_u32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 |
           std::uint32_t(p[3]);
}

bool is_png(std::span<const std::uint8_t> encoded) {
    static constexpr std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    return encoded.size() >= 8 && std::equal(signature, signature + 8, encoded.begin());
}

// A PNG's chunks, each (length, type, data, CRC-32 of type and data) up to
// IEND (PNG, ISO/IEC 15948, 5.3), inside the file and with the checksums they
// state: stb decodes without reading them, so a damaged file gave whatever
// pixels its damage made.
void check_png_chunks(std::span<const std::uint8_t> encoded, const std::string& name) {
    if (!is_png(encoded)) return;
    for (std::size_t at = 8;;) {
        if (!range_fits(at, 12, encoded.size()))
            throw_input_error(name, "byte " + std::to_string(at), "PNG ends without its IEND chunk");
        const std::size_t length = big_endian_u32(&encoded[at]);
        if (!range_fits(at + 8, length + 4, encoded.size()))
            throw_input_error(name, "byte " + std::to_string(at), "PNG chunk runs past the end of the file");
        const std::uint8_t* type = &encoded[at + 4];
        const std::string type_name(reinterpret_cast<const char*>(type), 4);
#ifndef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION  // renderer/CMakeLists.txt
        if (std::uint32_t(crc32(crc32(0, nullptr, 0), type, uInt(length + 4))) !=
            big_endian_u32(&encoded[at + 8 + length]))
            throw_input_error(name, "byte " + std::to_string(at),
                              "PNG chunk " + type_name + " fails its checksum (a damaged file)");
#endif
        if (type_name == "IEND") return;
        at += 12 + length;
    }
}

// stb's reason, or a general one where it gives none (as for some formats it knows only by name).
std::string decode_failure() {
    const char* reason = stbi_failure_reason();
    return std::string("cannot decode image: ") +
           (reason && *reason ? reason : "not an image format boxlod reads");
}

// The header read before decoding: no allocation for a size the file only claims.
ImageSize header_size(std::span<const std::uint8_t> encoded, const std::string& name) {
    int width = 0, height = 0, channels = 0;
    if (encoded.size() > std::size_t(std::numeric_limits<int>::max()))
        throw_input_error(name, "", "image file too large");
    const auto check_sides = [&](std::uint32_t w, std::uint32_t h) {
        if (w > std::uint32_t(max_image_side) || h > std::uint32_t(max_image_side))
            throw_input_error(name, "",
                              "image is " + std::to_string(w) + "x" + std::to_string(h) +
                                  " pixels, more than " + std::to_string(max_image_side) + " per side");
    };
    // A PNG's size from its IHDR first (PNG 11.2.2): stb refuses one too large under another reason.
    if (is_png(encoded) && encoded.size() >= 24 &&
        std::equal(encoded.begin() + 12, encoded.begin() + 16, std::string_view("IHDR").begin()))
        check_sides(big_endian_u32(&encoded[16]), big_endian_u32(&encoded[20]));
    if (!stbi_info_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels))
        throw_input_error(name, "", decode_failure());
    check_sides(std::uint32_t(width), std::uint32_t(height));
    check_png_chunks(encoded, name);
    return {width, height};
}

void check_image_header(std::span<const std::uint8_t> encoded, const std::string& name) {
    const ImageSize size = header_size(encoded, name);
    // Decoding is bounded by the size the header declares: RGBA8, and stb's copy of it.
    check_memory(
        name + ": decoding its " + std::to_string(size.width) + "x" + std::to_string(size.height) + " pixels",
        8.0 * double(size.width) * double(size.height));
}
}  // namespace

bool is_grey16(std::span<const std::uint8_t> encoded) {
    int width = 0, height = 0, channels = 0,
        size = int(std::min<std::size_t>(encoded.size(), std::numeric_limits<int>::max()));
    return stbi_is_16_bit_from_memory(encoded.data(), size) &&
           stbi_info_from_memory(encoded.data(), size, &width, &height, &channels) && channels == 1;
}

Image8 decode_image(std::span<const std::uint8_t> encoded, const std::string& name) {
    check_image_header(encoded, name);
    int width = 0, height = 0, channels_in_file = 0;
    stbi_uc* data =
        stbi_load_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels_in_file, 4);
    if (!data) throw_input_error(name, "", decode_failure());
    Image8 image(width, height, 4);
    std::copy(data, data + image.pixels.size(), image.pixels.begin());
    stbi_image_free(data);
    return image;
}

Image8 read_image(const std::string& path) {
    std::string bytes = read_input_file(path, "image file");
    return decode_image({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, path);
}

ImageSize read_image_size(const std::string& path) {
    std::string bytes = read_input_file(path, "image file");
    return header_size({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, path);
}

namespace {

// PNG through libspng (zlib). Baked pages are mostly flat colour: no row filter
// and zlib level 2 write them faster and smaller than stb's encoder at its
// level 5 (png_benchmark; docs/performance.md: Writing PNGs).
constexpr int png_compression_level = 2;

std::vector<std::uint8_t> encode_with_spng(const void* pixels, std::size_t size, int width, int height,
                                           int bit_depth, int channels) {
    static constexpr std::uint8_t color_types[] = {SPNG_COLOR_TYPE_GRAYSCALE, SPNG_COLOR_TYPE_GRAYSCALE_ALPHA,
                                                   SPNG_COLOR_TYPE_TRUECOLOR,
                                                   SPNG_COLOR_TYPE_TRUECOLOR_ALPHA};
    if (channels < 1 || channels > 4) throw std::logic_error("encode_png: 1 to 4 channels");
    std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> context(spng_ctx_new(SPNG_CTX_ENCODER), spng_ctx_free);
    if (!context) throw std::bad_alloc();
    spng_ctx* c = context.get();
    spng_set_option(c, SPNG_ENCODE_TO_BUFFER, 1);
    spng_set_option(c, SPNG_IMG_COMPRESSION_LEVEL, png_compression_level);
    spng_set_option(c, SPNG_FILTER_CHOICE, SPNG_FILTER_CHOICE_NONE);
    spng_ihdr header{};
    header.width = std::uint32_t(width);
    header.height = std::uint32_t(height);
    header.bit_depth = std::uint8_t(bit_depth);
    header.color_type = color_types[channels - 1];
    int error = spng_set_ihdr(c, &header);
    // SPNG_FMT_PNG: the samples as the PNG holds them, 16-bit ones in host byte order.
    if (!error) error = spng_encode_image(c, pixels, size, SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE);
    std::size_t length = 0;
    void* png = error ? nullptr : spng_get_png_buffer(c, &length, &error);
    if (!png) throw std::runtime_error(std::string("PNG encoding failed: ") + spng_strerror(error));
    std::vector<std::uint8_t> bytes(static_cast<std::uint8_t*>(png),
                                    static_cast<std::uint8_t*>(png) + length);
    std::free(png);
    return bytes;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image8& image) {
    return encode_with_spng(image.pixels.data(), image.pixels.size(), image.width, image.height, 8,
                            image.channels);
}

void write_png(const std::string& path, const Image8& image) {
    write_file_atomically(path, encode_png(image));
}

std::vector<std::uint8_t> encode_png16(const Image16& image) {
    if (image.channels == 1)
        return encode_with_spng(image.pixels.data(), image.pixels.size() * 2, image.width, image.height, 16,
                                1);
    Image16 grey(image.width, image.height, 1);  // the first channel
    for (std::size_t i = 0; i < grey.pixels.size(); ++i)
        grey.pixels[i] = image.pixels[i * std::size_t(image.channels)];
    return encode_with_spng(grey.pixels.data(), grey.pixels.size() * 2, grey.width, grey.height, 16, 1);
}

void write_png16(const std::string& path, const Image16& image) {
    write_file_atomically(path, encode_png16(image));
}

Image16 decode_image16(std::span<const std::uint8_t> encoded, const std::string& name) {
    check_image_header(encoded, name);
    int width = 0, height = 0, channels = 0;
    stbi_us* data =
        stbi_load_16_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels, 1);
    if (!data) throw_input_error(name, "", decode_failure());
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
}  // namespace

const std::array<float, 256> srgb_to_linear_table = make_srgb_table();

std::uint8_t linear_to_srgb(float value) {
    // The code is the number of midpoints between the decode table's values (in
    // encoded space: round to nearest) at or below `value`: the exact inverse of
    // srgb_to_linear for every 8-bit value, and no pow() per pixel.
    static const std::array<float, 255> midpoints = [] {
        std::array<float, 255> m{};
        for (int i = 0; i < 255; ++i) {
            double a = srgb_to_linear_table[i], b = srgb_to_linear_table[i + 1];
            double ea = a <= 0.0031308 ? a * 12.92 : 1.055 * std::pow(a, 1 / 2.4) - 0.055;
            double eb = b <= 0.0031308 ? b * 12.92 : 1.055 * std::pow(b, 1 / 2.4) - 0.055;
            double mid = (ea + eb) / 2;
            m[i] = float(mid <= 0.04045 ? mid / 12.92 : std::pow((mid + 0.055) / 1.055, 2.4));
        }
        return m;
    }();
    // The count at the smallest float of each bucket of floats sharing their top
    // 16 bits (sign, exponent, 7 mantissa bits), for every float in (0, 1): from
    // there at most a step or two reaches the exact count.
    constexpr std::uint32_t buckets = 0x3f800000u >> 16;  // 1.0f's bucket
    static const std::array<std::uint8_t, buckets> bucket_start = [] {
        std::array<std::uint8_t, buckets> start{};
        for (std::uint32_t b = 0; b < buckets; ++b) {
            float lowest = std::bit_cast<float>(b << 16);
            start[b] = std::uint8_t(std::upper_bound(midpoints.begin(), midpoints.end(), lowest) -
                                    midpoints.begin());
        }
        return start;
    }();
    if (!(value > 0.0f)) return 0;  // and NaN
    if (value >= 1.0f) return 255;  // every midpoint is below 1
    unsigned code = bucket_start[std::bit_cast<std::uint32_t>(value) >> 16];
    while (code < 255 && midpoints[code] <= value) ++code;
    return std::uint8_t(code);
}

}  // namespace boxlod
