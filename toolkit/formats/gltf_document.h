// The glTF document boxlod writes for a model or a chain of levels
// (toolkit/formats/gltf_io.h says what it holds), as tinygltf's structs;
// toolkit/formats/gltf_json.h turns it into a file's text.
#pragma once
#include "toolkit/model/lod_switch.h"
#include "toolkit/model/model.h"

#include <tiny_gltf.h>

#include <filesystem>
#include <vector>

namespace boxlod {

// `levels` finest first, one switch per level after the first (export_gltf_lods).
// Buffer 0 holds the geometry, and for a .glb (`binary`) the images too; for
// a .gltf the images are written as PNG files beside `target`, into the
// caller's output group, and buffer 0's uri is the file name to write it as
// (NAME.bin, another where that is a file the levels were read with). Buffers 1.. hold a chain level's first
// index list each (Babylon.js loads the levels in order so), written as data URIs.
tinygltf::Model gltf_document(const std::vector<const Model*>& levels, const std::vector<LodSwitch>& switches,
                              const std::filesystem::path& target, bool binary, int threads);

}  // namespace boxlod
