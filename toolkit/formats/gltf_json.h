// A glTF document's file: its JSON text and the .glb container, written
// straight into one string. tinygltf's writer builds a tree of nlohmann
// objects first, which took two thirds of writing a level (issue 72); this
// writes the same JSON (the same members, keys in the order of nlohmann's
// sorted objects, compact, numbers as nlohmann lays them out) for the members
// boxlod's documents use, and refuses a document with others (animations,
// skins, cameras, lights, sparse accessors) rather than drop them. A node's
// extras_json_string, where set, is its extras (gltf_extras.h: node_extras_json).
#pragma once
#include <tiny_gltf.h>

#include <string>

namespace boxlod {

// The .gltf text, compact (a third the size indented text takes), ending in
// a newline. Buffer 0
// is named by `bin_uri` (the .bin beside it); the other buffers are written
// as data URIs.
std::string gltf_text(const tinygltf::Model& document, const std::string& bin_uri);

// A file beside the document as a glTF uri (glTF 2.0, 2.8: RFC 3986 URI
// references): every byte but letters, digits and "-._~" percent-encoded, so
// that "my house%.bin" is read back as that file (clients decode the uri).
std::string file_uri(const std::string& file_name);
// The file a uri names, its %XX escapes decoded and '+' read as a space, as
// tinygltf decodes a uri before reading the file.
std::string file_name_of_uri(const std::string& uri);

// The .glb bytes (glTF 2.0, 4.4): a header, the compact JSON chunk padded
// with spaces, buffer 0 as the BIN chunk padded with zeros.
std::string glb_bytes(const tinygltf::Model& document);

}  // namespace boxlod
