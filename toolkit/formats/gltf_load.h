// tinygltf's model of a glTF's bytes, read with boxlod's callbacks: buffers
// and images named by URI read as every input file is (a folder, a device or
// a missing file is a clear error), and images by boxlod's decoders, so that
// a broken image is named by its own file and a claimed size is checked
// against the memory budget before anything is allocated.
#pragma once
#include <tiny_gltf.h>

#include <string>
#include <string_view>

namespace boxlod {

// `binary` for .glb; an image is RGBA8, or 16-bit grey where the file's is
// (height maps). Throws InputError naming `path`.
tinygltf::Model load_gltf(std::string_view bytes, bool binary, const std::string& path);

}  // namespace boxlod
