// The CPU renderer: draws flat batches (vertex arrays + surface) into a frame,
// deterministically and in parallel (docs/design.md: Rendering, Determinism).
//
//   Frame frame = make_frame(1024, 768, background);
//   render(batches, settings, frame);
//   write_png("out.png", frame_to_srgb8(frame));
#pragma once
#include "renderer/image.h"
#include "renderer/scene.h"

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

namespace boxlod {

// What a render leaves per pixel. Uncovered pixels keep the background,
// alpha 0, depth +infinity, normal 0. Depth and normal are the nearest
// surface's, blended or not; alpha is 1 under an opaque surface, else what the
// blended ones composite to over 0.
struct Frame {
    int width = 0, height = 0;
    std::vector<Eigen::Vector4f> color;   // linear RGB, alpha = coverage
    std::vector<float> depth;             // window depth in [0, 1]
    std::vector<Eigen::Vector3f> normal;  // world-space shading normal, facing the camera
};

// Refuses (InputError, base/memory_budget.h) a frame larger than the memory budget.
Frame make_frame(int width, int height, const Eigen::Vector3f& background);
// What rendering a width x height image and writing it needs: the frame, its
// visibility buffer and its encoded copy, 40 bytes a pixel (a little over
// what `boxlod render` peaks at, docs/testing.md: Hardening).
double render_memory(int width, int height);
void render(const std::vector<Batch>& batches, const RenderSettings& settings, Frame& frame);
// `frame` averaged over blocks of factor x factor pixels, its sides divided by `factor`
// (std::invalid_argument unless factor >= 1 divides both): supersampling, the anti-aliasing of the hybrid's
// measuring and of shots that ask for it. Colour and coverage only; depth and normals are dropped.
Frame downsample(const Frame& frame, int factor);

Image8 frame_to_srgb8(const Frame& frame);  // RGB, sRGB-encoded
Image8 coverage_mask(const Frame& frame);   // 255 where covered

}  // namespace boxlod
