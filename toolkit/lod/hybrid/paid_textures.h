// The textures a level pays for, as cost.h counts them: each distinct texture
// (known by its digest) once, however many drawn parts sample it. The hybrid
// plan prices a change with it: the change's meshes, plus the textures it
// brings in that no drawn part samples yet, less those no part samples after
// it (docs/design.md: The hybrid level mode).
#pragma once
#include "toolkit/model/model.h"

#include <vector>

namespace boxlod {

struct PaidTextures {
    std::vector<double> bytes;                  // per distinct texture: GPU bytes with mips (cost.h)
    std::vector<std::vector<int>> of_material;  // per material: its distinct textures, ascending
};
PaidTextures paid_textures(const Model& model);

// The distinct textures `primitives` sample, ascending; and a set with another added.
std::vector<int> textures_of(const PaidTextures& paid, const std::vector<Primitive>& primitives);
std::vector<int> united(const std::vector<int>& a, const std::vector<int>& b);
double bytes_of(const PaidTextures& paid, const std::vector<int>& textures);
// Per node, the distinct textures its own primitives sample, and those its whole sub-tree samples.
std::vector<std::vector<int>> node_textures(const Model& model, const PaidTextures& paid);
std::vector<std::vector<int>> subtree_textures(const Model& model, const PaidTextures& paid);
// Per node, the distinct textures that only its sub-tree samples: those a
// stand-in for the sub-tree can free.
std::vector<std::vector<int>> exclusive_textures(const Model& model, const PaidTextures& paid);

// How many drawn parts sample each distinct texture.
class DrawnTextures {
public:
    explicit DrawnTextures(const PaidTextures& paid) : paid_(paid), parts_(paid.bytes.size(), 0) {}
    // The bytes a change costs that stops drawing a part sampling `removed`
    // and starts drawing parts sampling `added`; apply() also makes it.
    double change(const std::vector<int>& removed, const std::vector<const std::vector<int>*>& added);
    double apply(const std::vector<int>& removed, const std::vector<const std::vector<int>*>& added);

private:
    const PaidTextures& paid_;
    std::vector<int> parts_;  // per distinct texture
};

}  // namespace boxlod
