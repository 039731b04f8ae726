// Keyframe files (experiments/city/camera_path.h), then poses sampled along them.
#include "experiments/city/camera_path.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return boxlod::fuzz::expect_only_input_errors([&] {
        auto keys = boxlod::parse_keyframes(boxlod::fuzz::text(data, size), "fuzz.keys");
        boxlod::sample_keyframes(keys, 8);
    });
}
