#include "toolkit/lod/hybrid/hybrid_measuring.h"

#include "renderer/image.h"
#include "renderer/scene.h"

#include <algorithm>
#include <cmath>

namespace boxlod {
namespace {

// Each view rendered at twice the side and averaged over 2 x 2 pixels: without
// it, detail near the pixel's size aliases differently in the sub-tree and in
// a texture baked from it, and the error measures the aliasing.
constexpr int supersampling = 2;

ComparedPixel compared_pixel(const Eigen::Vector4f& linear) {
    return {std::clamp(linear.w(), 0.0f, 1.0f),
            {linear_to_srgb(linear[0]), linear_to_srgb(linear[1]), linear_to_srgb(linear[2])}};
}

double compared_pixel_error(const ComparedPixel& a, const ComparedPixel& b) {
    double colour = 0;
    for (int c = 0; c < 3; ++c) colour += std::abs(a.srgb[std::size_t(c)] - b.srgb[std::size_t(c)]);
    return double(std::abs(a.coverage - b.coverage)) +
           double(std::min(a.coverage, b.coverage)) * colour / (3 * 255.0);
}

}  // namespace

std::vector<Frame> render_views(const std::vector<Batch>& batches, const MeasuringView& view, RenderMode mode,
                                const std::vector<Frame>* underlay, bool downsampled) {
    std::vector<Frame> frames;
    const float r = view.sphere.radius, half = view.pixel * float(view.side) / 2;
    for (int k = 0; k < measuring_directions; ++k) {
        const int corner = measuring_corners[std::size_t(k)];
        const Eigen::Vector3f direction =
            Eigen::Vector3f(corner & 1 ? 1.f : -1.f, corner & 2 ? 1.f : -1.f, corner & 4 ? 1.f : -1.f)
                .normalized();
        RenderSettings settings;
        settings.mode = mode;
        settings.threads = 1;  // nodes are measured in parallel
        settings.depth_from_frame = underlay != nullptr;
        settings.camera = orthographic_camera(view.sphere.center + direction * (2 * r), view.sphere.center,
                                              Eigen::Vector3f::UnitY(), {half, half}, r * 0.5f, r * 3.5f);
        settings.light = light_for_camera(settings.camera);
        frames.push_back(underlay
                             ? (*underlay)[std::size_t(k)]
                             : make_frame(view.side * supersampling, view.side * supersampling, {0, 0, 0}));
        render(batches, settings, frames.back());
        if (downsampled) frames.back() = downsample(frames.back(), supersampling);
    }
    return frames;
}

std::vector<std::vector<ComparedPixel>> compared_views(const std::vector<Frame>& frames) {
    std::vector<std::vector<ComparedPixel>> views;
    for (const Frame& frame : frames) {
        views.emplace_back();
        views.back().reserve(frame.color.size());
        for (const Eigen::Vector4f& c : frame.color) views.back().push_back(compared_pixel(c));
    }
    return views;
}

double pixel_error_sum(const std::vector<std::vector<ComparedPixel>>& original,
                       const std::vector<std::vector<ComparedPixel>>& proxy) {
    double sum = 0;
    for (std::size_t v = 0; v < original.size(); ++v)
        for (std::size_t i = 0; i < original[v].size(); ++i)
            sum += compared_pixel_error(original[v][i], proxy[v][i]);
    return sum;
}

double hybrid_pixel_error(const Eigen::Vector4f& a, const Eigen::Vector4f& b) {
    return compared_pixel_error(compared_pixel(a), compared_pixel(b));
}

}  // namespace boxlod
