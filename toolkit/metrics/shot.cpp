#include "toolkit/metrics/shot.h"

namespace boxlod {

Shot render_shot(const std::vector<Batch>& batches, const RenderSettings& settings, int width, int height,
                 int supersampling) {
    Frame frame = make_frame(width * supersampling, height * supersampling, {1, 1, 1});
    render(batches, settings, frame);
    if (supersampling > 1) frame = downsample(frame, supersampling);
    Shot shot;
    shot.image = frame_to_srgb8(frame);
    shot.coverage = coverage_from_mask(coverage_mask(frame));
    return shot;
}

}  // namespace boxlod
