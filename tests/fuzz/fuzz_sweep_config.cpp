// Sweep configs (experiments/sweep/sweep_config.h).
#include "experiments/sweep/sweep_config.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return boxlod::fuzz::expect_only_input_errors(
        [&] { boxlod::parse_sweep_config(boxlod::fuzz::text(data, size), "fuzz.txt"); });
}
