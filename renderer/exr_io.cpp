#include "renderer/exr_io.h"

#include "base/atomic_write.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <half.h>

#include <cmath>
#include <limits>

namespace boxlod {

std::vector<float> view_depth(const Frame& frame, const Camera& camera) {
    float n = camera.near_plane, f = camera.far_plane;
    std::vector<float> depth(frame.depth.size());
    for (std::size_t i = 0; i < depth.size(); ++i) {
        float d = frame.depth[i];
        if (!std::isfinite(d)) {
            depth[i] = std::numeric_limits<float>::infinity();
            continue;
        }
        float z_ndc = 2 * d - 1;  // invert the projection's depth mapping
        depth[i] = camera.orthographic ? n + d * (f - n) : 2 * f * n / ((f + n) - z_ndc * (f - n));
    }
    return depth;
}

void write_exr(const std::string& path, const Frame& frame, const Camera& camera) {
    std::size_t n = frame.color.size();
    std::vector<half> rgba(n * 4);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 4; ++c) rgba[i * 4 + c] = half(frame.color[i][c]);
    std::vector<float> z = view_depth(frame, camera);
    write_atomically(path, [&](const std::string& temporary) {
        Imf::Header header(frame.width, frame.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        const char* names[4] = {"R", "G", "B", "A"};
        for (const char* name : names) header.channels().insert(name, Imf::Channel(Imf::HALF));
        header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
        Imf::OutputFile file(temporary.c_str(), header);
        Imf::FrameBuffer buffer;
        std::size_t pixel = sizeof(half) * 4, row = pixel * frame.width;
        for (int c = 0; c < 4; ++c)
            buffer.insert(names[c],
                          Imf::Slice(Imf::HALF, reinterpret_cast<char*>(rgba.data() + c), pixel, row));
        buffer.insert("Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(z.data()), sizeof(float),
                                      sizeof(float) * frame.width));
        file.setFrameBuffer(buffer);
        file.writePixels(frame.height);
    });
}

}  // namespace boxlod
