#include "toolkit/lod/surface_deviation.h"

#include "renderer/exr_io.h"
#include "toolkit/drawing/drawable.h"

#include <algorithm>
#include <cmath>

namespace boxlod {

SurfaceViews surface_views(const Model& model, const OrientedBox& frame, int max_side, int threads) {
    const std::unique_ptr<DrawableModel> drawable = make_drawable_model(model, nullptr, threads);
    const Eigen::Vector3f half = frame.half_extents.cwiseMax(1e-3f);
    const float pixel = 2 * half.maxCoeff() / float(max_side);
    // Geometry may stand a little outside the frame (a level's boxes of another kind).
    const float margin = half.maxCoeff();
    SurfaceViews views;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {1.f, -1.f}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            RenderSettings settings;
            settings.mode = RenderMode::untextured;  // only depth and coverage are read
            settings.threads = threads;
            settings.camera = orthographic_camera(
                frame.center + sign * frame.axes.col(axis).normalized() * (half[axis] + margin), frame.center,
                frame.axes.col(v).normalized(), {half[u] + pixel, half[v] + pixel}, 0,
                2 * (half[axis] + margin));
            const Camera& camera = settings.camera;
            const int width = std::max(1, int(std::ceil((camera.right - camera.left) / pixel)));
            const int height = std::max(1, int(std::ceil((camera.top - camera.bottom) / pixel)));
            Frame rendered = make_frame(width, height, {0, 0, 0});
            render(drawable->drawable.batches, settings, rendered);
            views.depth.push_back(view_depth(rendered, camera));
        }
    return views;
}

double surface_deviation(const SurfaceViews& original, const SurfaceViews& level) {
    double deviation = 0;
    for (std::size_t view = 0; view < original.depth.size(); ++view)
        for (std::size_t i = 0; i < original.depth[view].size(); ++i) {
            const float a = original.depth[view][i], b = level.depth[view][i];
            if (std::isfinite(a) && std::isfinite(b))
                deviation = std::max(deviation, double(std::abs(a - b)));
        }
    return deviation;
}

}  // namespace boxlod
