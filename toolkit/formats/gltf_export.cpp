// glTF export (toolkit/formats/gltf_io.h): the document (gltf_document.h)
// written as text (gltf_json.h), every file atomically.
#include "toolkit/formats/gltf_io.h"

#include "base/atomic_write.h"
#include "base/memory_budget.h"
#include "toolkit/formats/gltf_document.h"
#include "toolkit/formats/gltf_json.h"

#include <filesystem>

namespace boxlod {

namespace {

// What writing asks (docs/design.md: Errors): the models as they are held, 48 bytes a vertex and 4 an
// index, and two copies of their geometry as written, 44 and 4 (the document's buffer and the file's
// bytes). Measured: 24 M vertices and 47 M indices, a .glb of 712 MB, peaked at 3.8 GB; this says 3.83.
double writing_memory(const std::vector<const Model*>& levels) {
    double vertices = 0, indices = 0;
    for (const Model* level : levels)
        for (const Node& node : level->nodes)
            for (const Primitive& primitive : node.primitives) {
                vertices += double(primitive.positions.size());
                indices += double(primitive.indices.size());
            }
    return 48 * vertices + 4 * indices + 2 * (44 * vertices + 4 * indices);
}

}  // namespace

void export_gltf(const Model& model, const std::string& path, int threads) {
    export_gltf_lods({&model}, {}, path, threads);
}

std::string gltf_binary(const Model& model, int threads) {
    check_memory("the model's glTF bytes", writing_memory({&model}));
    return glb_bytes(gltf_document({&model}, {}, "model.glb", true, threads));
}

void export_gltf_lods(const std::vector<const Model*>& levels, const std::vector<LodSwitch>& switches,
                      const std::string& path, int threads) {
    check_memory(path + ": the model, as written", writing_memory(levels));
    OutputGroup files;  // images, .bin and .gltf: all or none; the .gltf, which names the others, comes last
    const std::filesystem::path target(path);
    const bool binary = target.extension() == ".glb";
    const tinygltf::Model document = gltf_document(levels, switches, target, binary, threads);
    if (binary) {
        write_text_atomically(path, glb_bytes(document));
    } else {
        const std::string& bin_name = document.buffers[0].uri;
        write_file_atomically((target.parent_path() / bin_name).string(), document.buffers[0].data);
        write_text_atomically(path, gltf_text(document, file_uri(bin_name)));
    }
    files.commit();
}

}  // namespace boxlod
