// Golden images, compared byte for byte (docs/testing.md: Tests).
#pragma once
#include "renderer/image.h"
#include "test_support.h"

namespace boxlod::test {

// Golden images: the render's pixels must equal the stored PNG's, byte for
// byte. To regenerate after an intended change: BOXLOD_UPDATE_GOLDEN=1 ctest,
// then commit the PNGs with the reason in the commit message.
inline void expect_golden(const Image8& image, const std::string& name) {
    std::filesystem::path path = std::filesystem::path(BOXLOD_GOLDEN_DIR) / (name + ".png");
    if (std::getenv("BOXLOD_UPDATE_GOLDEN")) {
        write_png(path.string(), image);
        return;
    }
    ASSERT_TRUE(std::filesystem::exists(path))
        << "missing golden " << path << " (BOXLOD_UPDATE_GOLDEN=1 makes it)";
    Image8 stored = read_image(path.string());  // RGBA
    Image8 rendered = decode_image(encode_png(image), name);
    bool same = stored.width == rendered.width && stored.height == rendered.height &&
                stored.pixels == rendered.pixels;
    EXPECT_TRUE(same) << "render differs from " << path << "; the new image is at " << path.string()
                      << ".new.png";
    if (!same) write_png(path.string() + ".new.png", image);
}

}  // namespace boxlod::test
