// A glTF's accessors read as numbers, every offset, stride and count checked
// against its buffer view and buffer first (glTF 2.0, 3.6.2), and its errors
// named by file and place: the reader under boxlod's glTF import.
#pragma once
#include <tiny_gltf.h>
#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace boxlod {

struct GltfAccessorReader {
    const tinygltf::Model& gltf;
    const std::string& file;

    // Throws InputError "file: place: what".
    [[noreturn]] void fail(const std::string& place, const std::string& what) const;
    // Accessor `index`'s elements of N components (2, 3 or 4), normalized integers mapped as 3.11 says.
    template <int N>
    std::vector<Eigen::Matrix<double, N, 1>> vectors(int index, const std::string& place) const;
    // Accessor `index` as indices: unsigned integer scalars.
    std::vector<std::uint32_t> indices(int index, const std::string& place) const;
};

}  // namespace boxlod
