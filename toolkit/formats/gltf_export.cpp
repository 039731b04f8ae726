// glTF export (toolkit/formats/gltf_io.h): the document (gltf_document.h)
// written as text (gltf_json.h), every file atomically.
#include "toolkit/formats/gltf_io.h"

#include "base/atomic_write.h"
#include "toolkit/formats/gltf_document.h"
#include "toolkit/formats/gltf_json.h"

#include <filesystem>

namespace boxlod {

void export_gltf(const Model& model, const std::string& path, int threads) {
    export_gltf_lods({&model}, {}, path, threads);
}

std::string gltf_binary(const Model& model, int threads) {
    return glb_bytes(gltf_document({&model}, {}, "model.glb", true, threads));
}

void export_gltf_lods(const std::vector<const Model*>& levels, const std::vector<LodSwitch>& switches,
                      const std::string& path, int threads) {
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
