// What a glTF or glb file must satisfy before tinygltf reads it: glTF 2 with
// no extension required that boxlod does not read, and so that no
// offset or nesting from a hostile file can reach memory outside it or
// overflow the stack (glTF 2.0 spec, sections 4.4 "Binary glTF" and 5.11
// "bufferView"): the glb header and chunks inside the file, the JSON nested at
// most max_nesting_depth deep and its tree within the memory budget
// (toolkit/formats/json_input.h), every buffer view inside its buffer, every
// image's buffer view present; every member boxlod reads of the kind the
// schema gives it (an alphaCutoff that is a string, an `extensions` that is
// an array), where tinygltf would skip it without a word.
#pragma once
#include <string>
#include <string_view>

namespace boxlod {

// `bytes` is the whole file; `binary` for .glb. Throws InputError naming `file`.
void check_gltf_structure(std::string_view bytes, bool binary, const std::string& file);

}  // namespace boxlod
