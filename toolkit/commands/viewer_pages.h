// boxlod's chain viewers (clients/chain_three.html: a THREE.LOD,
// clients/chain_babylon.html: Babylon's Mesh.addLODLevel), written beside a
// chain by `build --chain --viewer` and opening that chain by default.
#pragma once
#include <string>
#include <vector>

namespace boxlod {

// Writes STEM.three.html and STEM.babylon.html beside `chain_path`, each
// opening the chain when no ?file= is given; returns their paths.
std::vector<std::string> write_viewer_pages(const std::string& chain_path);

}  // namespace boxlod
