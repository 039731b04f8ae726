#include "toolkit/metrics/shot.h"

namespace boxlod {

Shot render_shot(const std::vector<Batch>& batches, const RenderSettings& settings, int width, int height) {
    Frame frame = make_frame(width, height, {1, 1, 1});
    render(batches, settings, frame);
    Shot shot;
    shot.image = frame_to_srgb8(frame);
    shot.coverage = coverage_from_mask(coverage_mask(frame));
    return shot;
}

}  // namespace boxlod
