// CityJSON and CityJSONSeq files (toolkit/formats/cityjson_import.h): a
// CityJSONSeq when a line after the first starts a JSON object.
#include "fuzz_target.h"
#include "toolkit/formats/cityjson_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string bytes = boxlod::fuzz::text(data, size);
    const bool sequence = bytes.find("\n{") != std::string::npos;
    // Texture files resolve inside a folder that does not exist: each is missing.
    return boxlod::fuzz::expect_only_input_errors([&] {
        boxlod::import_cityjson_bytes(
            bytes, sequence ? "/nonexistent/fuzz.city.jsonl" : "/nonexistent/fuzz.city.json");
    });
}
