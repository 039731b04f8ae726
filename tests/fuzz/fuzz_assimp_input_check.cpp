// The checks made before assimp reads a file (toolkit/formats/assimp_input_check.h):
// PLY and OFF headers, STEP/IFC references. The first byte picks the format.
#include "fuzz_target.h"
#include "toolkit/formats/assimp_input_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static const char* const extensions[] = {".ply", ".off", ".ifc"};
    std::string extension = extensions[data[0] % 3];
    return boxlod::fuzz::expect_only_input_errors([&] {
        boxlod::check_assimp_input(boxlod::fuzz::text(data + 1, size - 1), extension, "fuzz" + extension);
    });
}
