// Writing a level's glTF: boxlod's writer (toolkit/formats/gltf_json.h, the
// text written straight from the document) against tinygltf's writer on the
// same document (a tree of nlohmann objects, then its text): as tinygltf
// writes a compact .gltf and its .bin itself, and as boxlod used it before
// (indented, the buffer patched in as text). Each writes the .gltf and its
// .bin to the same folder. The model is level 0 of `build manual.glb
// --all-levels` (the original, 10,748 nodes with their scopes: an 11.8 MB
// .gltf), issue 72's case.
//   build/experiments/gltf_benchmark
#include "base/atomic_write.h"
#include "data_gen/interpreter.h"
#include "data_gen/samples.h"
#include "toolkit/formats/gltf_document.h"
#include "toolkit/formats/gltf_io.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

using namespace boxlod;
namespace fs = std::filesystem;

namespace {

const Model& manual() {
    static const Model model = generate_building(sample_grammar("manual"), BuildingOptions{});
    return model;
}

// A folder of this run's own, removed when the program ends.
struct ScratchFolder {
    fs::path path = fs::temp_directory_path() / ("boxlod_gltf_benchmark_" + std::to_string(::getpid()));
    ScratchFolder() { fs::create_directories(path); }
    ~ScratchFolder() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
};

fs::path folder() {
    static const ScratchFolder scratch;
    return scratch.path;
}

// The nodes' extras as tinygltf's writer takes them (tinygltf::Value, as
// boxlod built them before): read by tinygltf from their text, outside the
// timing, so the peer is spared making them.
void extras_as_values(tinygltf::Model& document) {
    std::string json = R"({"asset":{"version":"2.0"},"nodes":[)";
    for (std::size_t k = 0; k < document.nodes.size(); ++k)
        json += (k ? ",{" : "{") +
                (document.nodes[k].extras_json_string.empty()
                     ? ""
                     : "\"extras\":" + document.nodes[k].extras_json_string) +
                "}";
    json += "]}";
    tinygltf::Model read;
    std::string error, warning;
    if (!tinygltf::TinyGLTF().LoadASCIIFromString(&read, &error, &warning, json.c_str(),
                                                  unsigned(json.size()), ""))
        throw std::runtime_error(error);
    for (std::size_t k = 0; k < document.nodes.size(); ++k) {
        if (document.nodes[k].extras_json_string.empty()) continue;
        document.nodes[k].extras = read.nodes[k].extras;
        document.nodes[k].extras_json_string.clear();
    }
}

// The same document written by tinygltf: 0, as boxlod wrote it before (its
// stream writer, indented, the buffer embedded as a data URI and then
// pointed at the .bin as text); 2, as tinygltf writes a .gltf and its .bin
// itself (compact, the buffer not embedded), the fair peer.
void write_with_tinygltf(const Model& model, const fs::path& path, bool as_before, benchmark::State& state) {
    OutputGroup files;
    tinygltf::Model document = gltf_document({&model}, {}, path, false, 0);
    state.PauseTiming();
    extras_as_values(document);
    state.ResumeTiming();
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(nullptr, nullptr);
    if (!as_before) {
        if (!writer.WriteGltfSceneToFile(&document, path.string(), false, false, false, false))
            throw std::runtime_error("tinygltf could not write " + path.string());
        files.commit();
        return;
    }
    const std::string bin_name = path.stem().string() + ".bin";
    write_file_atomically((path.parent_path() / bin_name).string(), document.buffers[0].data);
    std::ostringstream stream;
    writer.WriteGltfSceneToStream(&document, stream, true, false);
    std::string json = stream.str();
    const std::string data_uri = "\"uri\": \"data:application/octet-stream;base64,";
    const std::size_t begin = json.find(data_uri), end = json.find('"', begin + data_uri.size());
    json.replace(begin, end + 1 - begin, "\"uri\": \"" + bin_name + "\"");
    write_text_atomically(path.string(), json);
    files.commit();
}

// range(0): 1 boxlod, 2 tinygltf's own .gltf writing, 0 boxlod before (tinygltf's stream writer, indented).
void BM_WriteManualLevel(benchmark::State& state) {
    const Model& model = manual();
    const fs::path path = folder() / "manual_lod_L0.gltf";
    for (auto _ : state) {
        if (state.range(0) == 1) {
            export_gltf(model, path.string());
        } else {
            write_with_tinygltf(model, path, state.range(0) == 0, state);
        }
    }
    state.counters["MB"] = double(fs::file_size(path)) * 1e-6;
}

}  // namespace

BENCHMARK(BM_WriteManualLevel)
    ->ArgName("writer")
    ->Arg(1)
    ->Arg(2)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_MAIN();
