// The peer for the rasterizer benchmarks: the same batches, camera and
// per-pixel shading drawn by Mesa's llvmpipe through OSMesa (off-screen
// OpenGL): Blinn-Phong, colour maps (sRGB) and tangent-space normal maps with
// boxlod's own mip chains, trilinear filtering, alpha cut-out at 0.5.
#pragma once
#include "renderer/renderer.h"

#include <memory>

namespace boxlod::bench {

class LlvmpipePeer {
public:
    // nullptr if no OSMesa context can be made. llvmpipe takes its thread count
    // from LP_NUM_THREADS when the first context is created.
    static std::unique_ptr<LlvmpipePeer> create(const std::vector<Batch>& batches,
                                                const RenderSettings& settings, int width, int height);
    ~LlvmpipePeer();
    void draw();                      // one frame, finished (glFinish)
    double covered_fraction() const;  // of the last frame: pixels not left black

    // The rasterizer threads llvmpipe started in this process (Mesa names
    // them "llvmpipe-N"): the benchmark checks it ran with the count it asked for.
    static int rasterizer_threads();

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace boxlod::bench
