// Parameter files (toolkit/lod/parameter_file.h).
#include "fuzz_target.h"
#include "toolkit/lod/parameter_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return boxlod::fuzz::expect_only_input_errors(
        [&] { boxlod::parse_parameters(boxlod::fuzz::text(data, size), "fuzz.txt"); });
}
