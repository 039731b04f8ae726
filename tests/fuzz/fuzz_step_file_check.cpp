// STEP (IFC) files as boxlod checks them before web-ifc or assimp reads them
// (toolkit/formats/step_file_check.h): statements, strings, comments, entity
// numbers of any length, reference graphs.
#include "fuzz_target.h"
#include "toolkit/formats/step_file_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes = boxlod::fuzz::text(data, size);
    return boxlod::fuzz::expect_only_input_errors(
        [&] { boxlod::check_step_file(bytes, "fuzz.ifc", boxlod::max_nesting_depth); });
}
