// The built-in materials a grammar names with material(...), and the model
// materials the interpreter makes from a shape's appearance (a material,
// optionally tinted by color(...) or given another texture(...)).
#pragma once
#include "toolkit/model/model.h"

#include <map>
#include <optional>
#include <string>

namespace boxlod {

struct Appearance {
    std::string material = "default";
    std::optional<Eigen::Vector3f> color;  // sRGB 0..1; multiplies the material's texture
    std::string texture;                   // "" = the material's own, "none" = untextured
};

bool is_material_name(const std::string& name);
std::string material_names();

// Gives every distinct appearance one model material, adding it and its
// procedural textures (colour + normal map) to the model on first use, so
// the model holds only what it uses, in order of first use.
class MaterialCache {
public:
    int index(Model& model, const Appearance& appearance);
    // Metres covered by one tile of the appearance's texture (1 if untextured).
    float tile_metres(const Appearance& appearance) const;

private:
    std::map<std::string, int> materials_;
    std::map<std::string, std::pair<int, int>> textures_;  // name -> colour, normal texture index
};

}  // namespace boxlod
