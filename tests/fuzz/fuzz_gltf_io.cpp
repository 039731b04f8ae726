// glTF and glb files (toolkit/formats/gltf_io.h): a glb when the bytes start with its magic.
#include "fuzz_target.h"
#include "toolkit/formats/gltf_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string bytes = boxlod::fuzz::text(data, size);
    bool binary = bytes.rfind("glTF", 0) == 0;
    // External URIs resolve inside a folder that does not exist: only data: URIs are read.
    return boxlod::fuzz::expect_only_input_errors([&] {
        boxlod::import_gltf_bytes(bytes, binary, binary ? "/nonexistent/fuzz.glb" : "/nonexistent/fuzz.gltf");
    });
}
