// The peer for the rasterizer benchmark: the same mesh, camera and per-pixel
// Blinn-Phong drawn by Mesa's llvmpipe through OSMesa (off-screen OpenGL).
#pragma once
#include "renderer/renderer.h"

#include <memory>

namespace boxlod::bench {

class LlvmpipePeer {
public:
    // nullptr if no OSMesa context can be made. llvmpipe takes its thread count
    // from LP_NUM_THREADS when the first context is created.
    static std::unique_ptr<LlvmpipePeer> create(const Mesh& mesh, const RenderSettings& settings, int threads);
    ~LlvmpipePeer();
    void draw();  // one frame, finished (glFinish)
    double covered_fraction() const;  // of the last frame: pixels not left black

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace boxlod::bench
