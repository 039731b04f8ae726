// Test images for the image metrics: flat colours, a deterministic textured
// pattern, box blurs of it, and rectangles.
#pragma once
#include "renderer/image.h"

#include <algorithm>
#include <cstdint>

namespace boxlod::test {

inline Image8 flat_image(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image8 image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = image.at(x, y);
            p[0] = r;
            p[1] = g;
            p[2] = b;
        }
    return image;
}

// Bars, a checker and a hashed speckle in every channel: edges, points and
// texture at several scales, no value clipped at 0 or 255.
inline Image8 pattern_image(int width, int height) {
    Image8 image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint32_t hash = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u;
            hash = (hash ^ (hash >> 13)) * 0x5bd1e995u;
            int bars = (x / 6) % 2 ? 90 : 0;
            int checker = ((x / 3 + y / 3) % 2) ? 60 : 0;
            int speckle = int(hash >> 27);  // 0..31
            std::uint8_t* p = image.at(x, y);
            p[0] = std::uint8_t(40 + bars + speckle);
            p[1] = std::uint8_t(50 + checker + speckle);
            p[2] = std::uint8_t(60 + (bars + checker) / 2 + (31 - speckle));
        }
    return image;
}

// Mean over the (2 radius + 1)^2 neighbourhood, clamped at the borders.
inline Image8 box_blur(const Image8& in, int radius) {
    Image8 out(in.width, in.height, in.channels);
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x)
            for (int c = 0; c < in.channels; ++c) {
                int sum = 0, count = 0;
                for (int dy = -radius; dy <= radius; ++dy)
                    for (int dx = -radius; dx <= radius; ++dx, ++count)
                        sum += in.at(std::clamp(x + dx, 0, in.width - 1),
                                     std::clamp(y + dy, 0, in.height - 1))[c];
                out.at(x, y)[c] = std::uint8_t((sum + count / 2) / count);
            }
    return out;
}

// A one-channel mask, 255 inside [x0, x1) x [y0, y1), 0 elsewhere.
inline Image8 rectangle_mask(int width, int height, int x0, int y0, int x1, int y1) {
    Image8 mask(width, height, 1);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) *mask.at(x, y) = 255;
    return mask;
}

}  // namespace boxlod::test
