// IFC files as boxlod checks them before web-ifc reads them
// (toolkit/formats/ifc_io.h: check_ifc_references): strings, comments and
// entity numbers of any length.
#include "fuzz_target.h"
#include "toolkit/formats/ifc_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes = boxlod::fuzz::text(data, size);
    return boxlod::fuzz::expect_only_input_errors([&] { boxlod::check_ifc_references(bytes, "fuzz.ifc"); });
}
