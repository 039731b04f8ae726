// Texture images (renderer/image.h): PNG and the other formats stb decodes, at 8 and 16 bits.
#include "fuzz_target.h"
#include "renderer/image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::span<const std::uint8_t> bytes(data, size);
    boxlod::fuzz::expect_only_input_errors([&] { boxlod::decode_image(bytes, "fuzz.png"); });
    return boxlod::fuzz::expect_only_input_errors([&] {
        if (boxlod::is_grey16(bytes)) boxlod::decode_image16(bytes, "fuzz.png");
    });
}
