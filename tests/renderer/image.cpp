#include "renderer/image.h"

#include "base/input_error.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

using namespace boxlod;

TEST(Image, PngRoundTripKeepsEveryByte) {
    Image8 image(7, 5, 4);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = std::uint8_t(i * 37 + 11);
    Image8 back = decode_image(encode_png(image), "memory");
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 5);
    EXPECT_EQ(back.pixels, image.pixels);
}

TEST(Image, PngEncodingIsDeterministic) {
    Image8 image(16, 16, 3, 99);
    EXPECT_EQ(encode_png(image), encode_png(image));
}

TEST(Image, WritePngLeavesNoTemporaryBehind) {
    auto folder = test::scratch_folder("write_png");
    write_png((folder / "a.png").string(), Image8(3, 3, 1, 7));
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) files += entry.is_regular_file();
    EXPECT_EQ(files, 1u);
    EXPECT_EQ(read_image((folder / "a.png").string()).pixels[0], 7);
}

TEST(Image, UndecodableBytesAreAnInputError) {
    std::vector<std::uint8_t> garbage{1, 2, 3, 4, 5};
    EXPECT_THROW(decode_image(garbage, "garbage.png"), InputError);
    EXPECT_THROW(read_image("/nonexistent/file.png"), InputError);
}

TEST(Image, APngChunkThatFailsItsChecksumIsRefused) {
    Image8 image(4, 3, 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = std::uint8_t(i * 7);
    std::vector<std::uint8_t> png = encode_png(image);
    EXPECT_EQ(decode_image(png, "ok.png").width, 4);
    std::vector<std::uint8_t> damaged = png;
    damaged[damaged.size() - 20] ^= 1;  // a bit inside the IDAT data: stb decoded it without a word
    try {
        decode_image(damaged, "damaged.png");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("damaged.png: byte 33: PNG chunk IDAT fails its checksum"),
                  std::string::npos)
            << error.what();
    }
    std::vector<std::uint8_t> cut(png.begin(), png.end() - 12);  // no IEND
    EXPECT_THROW(decode_image(cut, "cut.png"), InputError);
}

TEST(Image, ASizeBeyondTheLimitIsRefusedBeforeDecoding) {
    // A valid PNG header claiming 100000 x 1 pixels, with no pixel data.
    std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0,    0, 0,
                                     13,   'I', 'H', 'D', 'R',  0,    1,    0x86, 0xa0, 0, 0,
                                     0,    1,   8,   2,   0,    0,    0,    0,    0,    0, 0};
    try {
        decode_image(png, "wide.png");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()), "wide.png: image is 100000x1 pixels, more than 16384 per side");
    }
    EXPECT_FALSE(is_grey16(png));
    // 20000 x 20000: stb refuses it as "unknown image type" (too many bytes for it); the size is named.
    png[16] = 0, png[17] = 0, png[18] = 0x4e, png[19] = 0x20;
    png[20] = 0, png[21] = 0, png[22] = 0x4e, png[23] = 0x20;
    EXPECT_EQ(test::input_error_of([&] { decode_image(png, "square.png"); }),
              "square.png: image is 20000x20000 pixels, more than 16384 per side");
}

TEST(Image, SrgbEncodeInvertsDecodeForEveryByte) {
    for (int i = 0; i < 256; ++i) EXPECT_EQ(linear_to_srgb(srgb_to_linear(std::uint8_t(i))), i);
    EXPECT_EQ(linear_to_srgb(-1.0f), 0);
    EXPECT_EQ(linear_to_srgb(2.0f), 255);
    EXPECT_NEAR(srgb_to_linear(128), 0.21586, 1e-5);  // IEC 61966-2-1
    EXPECT_EQ(linear_to_srgb(0.5f), 188);             // 0.5 linear = 187.5 encoded, rounds to 188
}

TEST(Image, SrgbEncodeRoundsToNearestForEveryFloatItTries) {
    // The reference: the code whose encoded value is nearest, found by binary
    // search over the midpoints between codes (IEC 61966-2-1's formulas).
    std::vector<float> midpoints;
    auto encoded = [](double l) { return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1 / 2.4) - 0.055; };
    for (int i = 0; i < 255; ++i) {
        double mid =
            (encoded(srgb_to_linear(std::uint8_t(i))) + encoded(srgb_to_linear(std::uint8_t(i + 1)))) / 2;
        midpoints.push_back(float(mid <= 0.04045 ? mid / 12.92 : std::pow((mid + 0.055) / 1.055, 2.4)));
    }
    auto reference = [&](float v) {
        if (!(v > 0)) return 0;
        return int(std::upper_bound(midpoints.begin(), midpoints.end(), v) - midpoints.begin());
    };
    int mismatches = 0;
    for (std::uint32_t bits = 1; bits < 0x3f800000u + 64;
         bits += 61) {  // every 61st float up to just above 1
        float v = std::bit_cast<float>(bits);
        mismatches += linear_to_srgb(v) != reference(v);
    }
    for (float m : midpoints)  // each midpoint and its neighbours, where the code changes
        for (float v : {std::nextafter(m, 0.0f), m, std::nextafter(m, 2.0f)})
            mismatches += linear_to_srgb(v) != reference(v);
    EXPECT_EQ(mismatches, 0);
    EXPECT_EQ(linear_to_srgb(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(linear_to_srgb(std::numeric_limits<float>::infinity()), 255);
}

TEST(Image, Png16RoundTripKeepsEverySample) {
    Image16 image(5, 3, 1);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = std::uint16_t(i * 4099 + 7);
    std::vector<std::uint8_t> png = encode_png16(image);
    EXPECT_EQ(decode_image16(png, "memory").pixels, image.pixels);
    EXPECT_EQ(png, encode_png16(image));
    // An 8-bit file read as 16 bits scales 255 to 65535.
    EXPECT_EQ(decode_image16(encode_png(Image8(1, 1, 1, 255)), "memory").pixels[0], 65535);
}
